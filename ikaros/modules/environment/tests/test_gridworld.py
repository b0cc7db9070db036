"""Tests of the GridWorld module: discrete moves in all four modes, rewards and restarts,
collisions, local views, the image, and the differential drive against the kinematic
formulas."""
import math

import numpy as np
import pytest

from ikaros.testing import load_body as load

# 6 rows x 7 columns; walls at the border and at (x=3, y=2) and (x=3, y=3)
OPEN = ("1 1 1 1 1 1 1; 1 0 0 0 0 0 1; 1 0 0 1 0 0 1; "
        "1 0 0 1 0 0 1; 1 0 0 0 0 0 1; 1 1 1 1 1 1 1")
WALLS = np.array([[float(v) for v in row.split()] for row in OPEN.split(";")], np.float32)


def world(tmp_path, move_size=4, values=None, **params):
    """A world with this project's COLLISION and IMAGE unless the test asks otherwise."""
    params = {"collision": "blocked", "image": "normalized", **params}
    attrs = " ".join(f'{k}="{v}"' for k, v in params.items())
    body = (f'<module class="Constant" name="Obst" data="{OPEN}"/>\n'
            f'<module class="Constant" name="Mv" data="{" ".join(["0"] * move_size)}"/>\n'
            f'<module class="GridWorld" name="G" {attrs}/>\n'
            '<connection source="Obst.OUTPUT" target="G.OBSTACLES" delay="0"/>\n'
            '<connection source="Mv.OUTPUT" target="G.MOVE" delay="0"/>\n')
    if values is not None:
        body += (f'<module class="Constant" name="Val" data="{values}"/>\n'
                 '<connection source="Val.OUTPUT" target="G.VALUES" delay="0"/>\n')
    return load(tmp_path, body)


def act(net, *move):
    net.set_parameter("Mv.data", " ".join(str(float(m)) for m in move))
    net.step()
    return tuple(net.output("G.COORDINATE")), float(net.output("G.COLLISION")[0])


def test_max_mode_moves_collides_and_reports_the_neighbourhood(tmp_path):
    net = world(tmp_path, start_x=2, start_y=2)
    try:
        assert tuple(net.output("G.COORDINATE")) == (2, 2)            # set in init
        assert net.output("G.LOCATION").shape == (6, 7)
        assert act(net, 1, 0, 0, 0) == ((2, 1), 0)                   # north
        assert act(net, 1, 0, 0, 0) == ((2, 1), 1)                   # border: blocked
        assert act(net, 0, 0.2, 0.1, 0) == ((3, 1), 0)               # east (largest)
        assert act(net, 0, 0, 1, 0) == ((3, 1), 1)                   # south is a wall
        assert act(net, 0, 0, 0, 1) == ((2, 1), 0)                   # west
        loc = net.output("G.LOCATION")
        assert loc.sum() == 1 and loc[1, 2] == 1
        assert np.array_equal(net.output("G.LOCAL_OBSTACLES"), WALLS[0:3, 1:4])
        assert np.array_equal(net.output("G.LOCAL_VALUES"), np.zeros((3, 3)))   # no VALUES
        assert net.output("G.HEADING")[0] == pytest.approx(3 * math.pi / 2)      # west
        expected = WALLS / 3
        expected[1, 2] = 2 / 3
        assert np.allclose(net.output("G.IMAGE"), expected)
    finally:
        net.close()


def test_ikaros2_collision_and_image(tmp_path):
    """Ikaros 2's defaults (golden-v2 GridWorld): COLLISION 0 on a blocked move and 1 on a
    move that succeeds; IMAGE is OBSTACLES with 3 on rewards and 2 at the agent."""
    values = "0 0 0 0 0 0 0; 0 0 0 0 0 2 0; 0 0 0 0 0 0 0; 0 0 0 0 0 0 0; " \
             "0 0 0 0 0 0 0; 0 0 0 0 0 0 0"
    net = world(tmp_path, values=values, start_x=2, start_y=2, collision="original",
                image="original")
    try:
        assert act(net, 1, 0, 0, 0) == ((2, 1), 1)                   # north: moved
        assert act(net, 1, 0, 0, 0) == ((2, 1), 0)                   # border: blocked
        expected = WALLS.copy()
        expected[1, 5] = 3
        expected[1, 2] = 2
        assert np.array_equal(net.output("G.IMAGE"), expected)
    finally:
        net.close()


def test_zero_move_does_nothing(tmp_path):
    net = world(tmp_path, start_x=4, start_y=4)
    try:
        for _ in range(3):
            assert act(net, 0, 0, 0, 0) == ((4, 4), 0)
            assert net.output("G.REWARD")[0] == 0
    finally:
        net.close()


def test_sum_mode_opposes_opposite_directions(tmp_path):
    net = world(tmp_path, move="sum", start_x=4, start_y=3)
    try:
        # N-S = 0.8, E-W = -0.4, S-N = -0.8, W-E = 0.4: north, although E/W are larger than S
        assert act(net, 1, 0.5, 0.2, 0.9) == ((4, 2), 0)
        # N-S = -0.5, E-W = 0.3, S-N = 0.5, W-E = -0.3: south, though east is larger than N
        assert act(net, 1, 0.8, 1.5, 0.5) == ((4, 3), 0)
        assert act(net, 0.2, 0.9, 0.2, 0.1) == ((5, 3), 0)  # E-W = 0.8: east
    finally:
        net.close()


def test_relative_modes_turn_both_ways(tmp_path):
    for move in ("relative_max", "relative_sum"):
        net = world(tmp_path, move_size=3, move=move, start_x=1, start_y=4)
        try:
            assert net.output("G.HEADING")[0] == 0                      # facing north
            assert act(net, 1, 0, 0) == ((1, 3), 0)                      # ahead (north)
            assert act(net, 0, 0, 1) == ((1, 3), 0)                      # turn right: east
            assert net.output("G.HEADING")[0] == pytest.approx(math.pi / 2)
            assert act(net, 1, 0, 0) == ((2, 3), 0)
            assert act(net, 1, 0, 0) == ((2, 3), 1)                      # wall at (3, 3)
            assert act(net, 0, 1, 0) == ((2, 3), 0)                      # turn left: north
            assert net.output("G.HEADING")[0] == 0
            assert act(net, 0, 1, 0) == ((2, 3), 0)                      # left again: west
            assert act(net, 1, 0, 0) == ((1, 3), 0)
        finally:
            net.close()
    # relative_sum: left and right oppose each other, so left 0.9 vs right 0.8 is a weak
    # left turn (0.1) that loses to ahead 0.5; relative_max would turn left.
    net = world(tmp_path, move_size=3, move="relative_sum", start_x=1, start_y=4)
    try:
        assert act(net, 0.5, 0.9, 0.8) == ((1, 3), 0)
    finally:
        net.close()


def test_reward_then_restart(tmp_path):
    values = "0 0 0 0 0 0 0; 0 0 0 0 0 0 0; 0 0 0 0 0 0 0; 0 0 0 0 0 0 0; " \
             "0 0 -0.5 0 0 1 0; 0 0 0 0 0 0 0"
    net = world(tmp_path, values=values, start_x=4, start_y=3)
    try:
        image = net.output("G.IMAGE")
        assert image[4, 5] == 1 and image[3, 4] == pytest.approx(2 / 3)
        assert act(net, 0, 0, 1, 0) == ((4, 4), 0)
        assert net.output("G.REWARD")[0] == 0
        assert np.array_equal(net.output("G.LOCAL_VALUES")[1], [0, 0, 1])
        assert act(net, 0, 1, 0, 0) == ((4, 3), 0)        # reached the reward: back at start
        assert net.output("G.REWARD")[0] == 1
        assert net.output("G.LOCATION")[3, 4] == 1
        assert act(net, 1, 0, 0, 0) == ((4, 2), 0)
        assert net.output("G.REWARD")[0] == 0
        # a negative value is reported but does not restart the agent
        net.command("G", "reset")
        for m in ((0, 0, 1, 0), (0, 0, 0, 1), (0, 0, 0, 1)):
            act(net, *m)
        assert tuple(net.output("G.COORDINATE")) == (2, 4)
        assert net.output("G.REWARD")[0] == -0.5
    finally:
        net.close()


def test_start_is_clamped_and_ikaros2_aliases_and_normalized_coordinate(tmp_path):
    net = world(tmp_path, x_start=7, y_start=0, start_x=2, normalize_coordinate="yes")
    try:
        # x_start overrides start_x; both clamp into the inner cells (1..5, 1..4)
        assert np.allclose(net.output("G.COORDINATE"), [(5 + 0.5) / 7, (1 + 0.5) / 6])
        assert net.output("G.LOCATION")[1, 5] == 1
    finally:
        net.close()


def test_unconnected_move_and_values(tmp_path):
    net = load(tmp_path, f'<module class="Constant" name="Obst" data="{OPEN}"/>'
                         '<module class="GridWorld" name="G"/>'
                         '<connection source="Obst.OUTPUT" target="G.OBSTACLES"/>')
    try:
        net.run(ticks=3)
        assert tuple(net.output("G.COORDINATE")) == (1, 1)
        assert net.output("G.REWARD")[0] == 0 and net.output("G.COLLISION")[0] == 0
    finally:
        net.close()


def test_bad_sizes_fail_at_build(tmp_path):
    with pytest.raises(Exception, match="MOVE has 2 elements"):
        world(tmp_path, move_size=2)
    with pytest.raises(Exception, match="VALUES"):
        world(tmp_path, values="0 0; 0 0")


# --- differential drive -----------------------------------------------------------------

def drive(net, left, right):
    net.set_parameter("Mv.data", f"{left} {right}")
    net.step()
    return (*net.output("G.COORDINATE").astype(float), float(net.output("G.HEADING")[0]),
            float(net.output("G.COLLISION")[0]))


def test_differential_drive_follows_the_kinematics(tmp_path):
    net = world(tmp_path, move_size=2, motion="differential_drive", start_x=1, start_y=4,
                wheel_base=0.5, radius=0.3, max_speed=0.25)
    try:
        x, y, h = 1.0, 4.0, 0.0
        # straight ahead (north = -y), 0.2 cells per tick
        got = drive(net, 0.2, 0.2)
        y -= 0.2
        assert got == pytest.approx((x, y, h, 0), abs=1e-5)
        # turn on the spot, clockwise: (left - right) / wheel_base = 0.4 rad
        got = drive(net, 0.1, -0.1)
        h += 0.4
        assert got == pytest.approx((x, y, h, 0), abs=1e-5)
        # an arc: v = 0.15, w = (0.2 - 0.1) / 0.5 = 0.2; exact integration over one tick
        got = drive(net, 0.2, 0.1)
        v, w = 0.15, 0.2
        x += v / w * (math.cos(h) - math.cos(h + w))
        y += v / w * (math.sin(h) - math.sin(h + w))
        h += w
        assert got == pytest.approx((x, y, h, 0), abs=1e-5)
        # wheel speeds are clipped to max_speed: 1.0 -> 0.25 per tick
        hx, hy = math.sin(h), -math.cos(h)
        got = drive(net, 1.0, 1.0)
        assert got == pytest.approx((x + 0.25 * hx, y + 0.25 * hy, h, 0), abs=1e-5)
        loc = net.output("G.LOCATION")
        cx, cy = int(math.floor(got[0] + 0.5)), int(math.floor(got[1] + 0.5))
        assert loc.sum() == 1 and loc[cy, cx] == 1
    finally:
        net.close()


def test_differential_drive_stops_at_walls(tmp_path):
    net = world(tmp_path, move_size=2, motion="differential_drive", start_x=2, start_y=3,
                radius=0.3)
    try:
        # drive north 0.15 per tick: the border row 0 covers y <= 0.5, so the disc's centre
        # cannot go below y = 0.8; from y = 3 it stops at 0.9 (the next step, 0.75, is refused)
        collisions = [drive(net, 0.15, 0.15)[3] for _ in range(20)]
        x, y = net.output("G.COORDINATE")
        assert x == pytest.approx(2) and y == pytest.approx(0.9, abs=1e-4)
        assert collisions[:14] == [0] * 14 and collisions[14:] == [1] * 6
        # facing east from (2, 3), the wall cell (3, 3) has its edge at x = 2.5
        net.set_parameter("G.start_heading", math.pi / 2)
        net.command("G", "reset")
        for _ in range(5):
            got = drive(net, 0.15, 0.15)
        assert got == pytest.approx((2.15, 3, math.pi / 2, 1), abs=1e-4)
    finally:
        net.close()


def test_differential_drive_reward_restarts(tmp_path):
    values = "0 0 0 0 0 0 0; 0 0 0 0 0 0 0; 0 0 0 0 0 0 0; 0 0 0 0 0 0 0; " \
             "0 0 0 0 0 1 0; 0 0 0 0 0 0 0"
    net = world(tmp_path, move_size=2, values=values, motion="differential_drive",
                start_x=4, start_y=4, start_heading=math.pi / 2)
    try:
        rewards = []
        for _ in range(4):                       # 0.2 per tick: the cell x = 5 from x >= 4.5
            drive(net, 0.2, 0.2)
            rewards.append(float(net.output("G.REWARD")[0]))
        assert rewards == [0, 0, 1, 0]
        assert net.output("G.COORDINATE")[0] == pytest.approx(4.2)
    finally:
        net.close()
