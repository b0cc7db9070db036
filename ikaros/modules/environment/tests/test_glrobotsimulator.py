"""GLRobotSimulator: Ikaros 2's start, DIRECT_CONTROL, empty tables and range map; picking,
stacking and placing blocks, driving, collisions, battery and the 3-D scene (in a 1.5 m
arena)."""
import math

import numpy as np
import pytest

from ikaros.testing import load_body

OBJECTS = "1 1 1100 300 0 0.3; 1 2 1100 400 0 0.6; 2 7 400 1000 0 0.9"
ARENA = 'arena_size="1500 1500" start="1300 225 3.1416"'


def build(tmp_path, script, params=ARENA, objects=OBJECTS, extra=""):
    """A robot driven by an InputFile ``script``: column names, then one row per tick; in a
    1.5 m arena starting at (1300, 225) facing -x unless ``params`` say otherwise."""
    (tmp_path / "script.txt").write_text(script)
    names = script.split("\n")[0].split()
    body = (f'<module class="Constant" name="Objects" data="{objects}"/>\n'
            '<module class="InputFile" name="S" filename="script.txt"/>\n'
            f'<module class="GLRobotSimulator" name="R" {params}/>\n'
            '<connection source="Objects.OUTPUT" target="R.OBJECTS_IN"/>\n' + extra)
    for column in names:
        name = column.split("/")[0]
        body += f'<connection source="S.{name}" target="R.{name}" delay="0"/>\n'
    return load_body(tmp_path, body)


def run(net, ticks, watch=()):
    seen = []
    for _ in range(ticks):
        net.step()
        seen.append({w: net.output(f"R.{w}").copy() for w in watch})
    return seen


def script(header, *rows):
    """header, then each (row, repeat) pair."""
    lines = [header] + [row for row, times in rows for _ in range(times)]
    return "\n".join(lines) + "\n"


def phase(seen, name):
    return [int(np.argmax(s[name])) for s in seen]


def test_pick_a_block_and_stack_it_on_another(tmp_path):
    net = build(tmp_path, script("PICK_OBJECT_ID/1 PICK_OBJECT_TRIGGER/1 "
                                 "PLACE_OBJECT_LOCATION/2 PLACE_OBJECT_TRIGGER/1",
                                 ("1 1 1100 400 0", 30), ("1 0 1100 400 1", 30)))
    try:
        seen = run(net, 60, ("PICK_PHASE", "PLACE_PHASE", "ROBOT_LOCATION", "BLOCKS",
                             "PICK_ERROR", "PLACE_ERROR"))
        # reaching arrives on its 10th tick, grasping takes 5, lifting 10; then done
        assert phase(seen[:30], "PICK_PHASE") == [1] * 9 + [2] * 5 + [3] * 10 + [4] * 6
        assert phase(seen[30:], "PLACE_PHASE") == [1] * 9 + [2] * 5 + [3] * 10 + [4] * 6
        assert seen[20]["ROBOT_LOCATION"][2] == 1                     # holding block 1
        assert seen[20]["BLOCKS"][0, 5] == 1
        assert seen[-1]["ROBOT_LOCATION"][2] == 0
        assert seen[-1]["BLOCKS"][0].tolist() == pytest.approx([1, 1100, 400, 50, 0.3, 0])
        assert seen[-1]["BLOCKS"][1].tolist() == pytest.approx([2, 1100, 400, 0, 0.6, 0])
        assert not any(s["PICK_ERROR"][0] or s["PLACE_ERROR"][0] for s in seen)
        out = net.output("R.OBJECTS_OUT")
        assert out.shape == (3, 6) and out[0].tolist() == pytest.approx([1, 1, 1100, 400, 50,
                                                                          0.3])
    finally:
        net.close()


@pytest.mark.parametrize("objects, pick_id", [
    (OBJECTS, 9),                                                   # no such block
    ("1 1 700 300 0 0.3", 1),                                       # out of reach (600 mm)
    ("1 1 1100 300 0 0.3; 1 2 1100 300 50 0.6", 1)])                # block 2 lies on it
def test_picks_that_cannot_be_done_are_errors(tmp_path, objects, pick_id):
    net = build(tmp_path, script("PICK_OBJECT_ID/1 PICK_OBJECT_TRIGGER/1", (f"{pick_id} 1", 3)),
                objects=objects)
    try:
        seen = run(net, 3, ("PICK_ERROR", "PICK_PHASE"))
        assert [s["PICK_ERROR"][0] for s in seen] == [1, 1, 1]
        assert all(not s["PICK_PHASE"].any() for s in seen)            # idle: all 0
    finally:
        net.close()


def test_spatial_attention_picks_the_nearest_block(tmp_path):
    net = build(tmp_path, script("PICK_OBJECT_SPATIAL_ATTENTION/2 PICK_OBJECT_TRIGGER/1",
                                 ("1090 410 1", 20)))
    try:
        run(net, 20)
        assert net.output("R.ROBOT_LOCATION")[2] == 2
    finally:
        net.close()


def test_drive_to_a_goal(tmp_path):
    net = build(tmp_path, script("GOAL_LOCATION/2 LOCOMOTION_TRIGGER/1 SPEED/1",
                                 ("1300 800 1 1", 80)))
    try:
        seen = run(net, 80, ("LOCOMOTION_PHASE", "ROBOT_LOCATION", "SPEED_OUT", "TARGET"))
        phases = phase(seen, "LOCOMOTION_PHASE")
        turning = math.ceil((math.pi / 2) / 0.1)          # from heading pi to pi/2
        driving = math.ceil(575 / 10)
        assert phases == [1] * (turning - 1) + [2] * driving + [3] * (81 - turning - driving)
        location = seen[-1]["ROBOT_LOCATION"]
        assert [location[0], location[1], location[3]] == pytest.approx(
            [1300, 800, math.pi / 2], abs=1e-3)
        assert seen[turning + 5]["SPEED_OUT"][0] == 1                # the SPEED input
        assert seen[turning + 5]["TARGET"].tolist() == [1300, 800, 0, 1]
        assert seen[-1]["TARGET"].tolist() == [-99999] * 4           # arrived: no target
    finally:
        net.close()


def test_a_trip_into_a_block_stops_with_an_error(tmp_path):
    net = build(tmp_path, script("GOAL_LOCATION/2 LOCOMOTION_TRIGGER/1", ("700 700 1", 100)))
    try:
        seen = run(net, 100, ("LOCOMOTION_PHASE", "LOCOMOTION_ERROR", "ROBOT_LOCATION"))
        assert phase(seen, "LOCOMOTION_PHASE")[-1] == 4 and seen[-1]["LOCOMOTION_ERROR"][0] == 1
        x, y = seen[-1]["ROBOT_LOCATION"][:2]
        nearest = min(math.hypot(x - 1100, y - 300), math.hypot(x - 1100, y - 400))
        assert 125 - 1e-6 <= nearest < 135          # stopped at a block (radii 100 + 25)
    finally:
        net.close()


def test_goals_outside_the_arena_are_errors(tmp_path):
    net = build(tmp_path, script("GOAL_LOCATION/2 LOCOMOTION_TRIGGER/1", ("1450 800 1", 2)))
    try:
        seen = run(net, 2, ("LOCOMOTION_ERROR",))
        assert seen[0]["LOCOMOTION_ERROR"][0] == 1                # 1450 + radius 100 > 1500
    finally:
        net.close()


def test_battery_decays_on_a_trip_and_charges_at_the_station(tmp_path):
    net = build(tmp_path, script("GOAL_LOCATION/2 LOCOMOTION_TRIGGER/1 CHARGE_BATTERIES/1",
                                 ("1380 225 1 1", 1), ("1380 225 1 0", 8), ("1380 225 1 1", 3)),
                params='arena_size="1500 1500" start="1300 225 0" battery_decay="0.01"')
    try:
        seen = run(net, 12, ("BATTERY_LEVEL", "CHARGE_ERROR", "CHARGE_PHASE", "ROBOT_LOCATION",
                             "LOCOMOTION_PHASE"))
        # tick 1 turns (no turn needed), ticks 2-9 drive 10 mm each: 9 ticks of 0.01
        assert seen[0]["CHARGE_ERROR"][0] == 1                    # 175 mm from the station
        assert seen[0]["CHARGE_PHASE"].tolist() == [0, 0]
        assert seen[0]["BATTERY_LEVEL"][0] == pytest.approx(0.99)
        assert seen[8]["ROBOT_LOCATION"][0] == pytest.approx(1380)
        assert seen[8]["BATTERY_LEVEL"][0] == pytest.approx(0.91)
        assert seen[8]["CHARGE_ERROR"][0] == 0
        # arrived 95 mm from the station: no use, 0.01 a tick charged
        assert seen[9]["CHARGE_PHASE"].tolist() == [0, 1] and seen[9]["CHARGE_ERROR"][0] == 0
        assert [s["BATTERY_LEVEL"][0] for s in seen[9:]] == pytest.approx([0.92, 0.93, 0.94])
    finally:
        net.close()


def test_ikaros2_start_and_direct_control(tmp_path):
    """Ikaros 2's robot starts at (100, 100) facing x; DIRECT_CONTROL (dx, dy, -, dheading)
    turns it at once and moves it on the next tick, kept 100 mm (its radius) from the walls;
    no battery is used; the third value of ROBOT_LOCATION is the held block (none)."""
    net = build(tmp_path, script("DIRECT_CONTROL/4", ("5 -3 0 0.5", 3)), params="",
                objects="0 0 0 0 0 0")
    try:
        seen = run(net, 3, ("ROBOT_LOCATION", "VIEW_FIELD", "BATTERY_LEVEL", "TARGET"))
        assert seen[0]["ROBOT_LOCATION"].tolist() == pytest.approx([100, 100, 0, 0.5])
        assert seen[1]["ROBOT_LOCATION"].tolist() == pytest.approx([105, 100, 0, 1.0])
        assert seen[2]["ROBOT_LOCATION"].tolist() == pytest.approx([110, 100, 0, 1.5])
        assert seen[1]["VIEW_FIELD"].tolist() == pytest.approx(
            [105 + 450 * math.cos(1.0), 100 + 450 * math.sin(1.0)], rel=1e-6)
        assert all(s["BATTERY_LEVEL"][0] == 1 for s in seen)
        assert seen[0]["TARGET"].tolist() == [-99999] * 4
    finally:
        net.close()


def test_range_map_and_view(tmp_path):
    """From (100, 100) facing x in the 1700 x 1200 arena: sector 16 (just left of the
    heading) sees the far wall 1600 away, sector 0 (behind) and sector 24 (to the right) the
    near walls 100 away, sector 8 (to the left) the wall 1100 away, or a block 475 away."""
    net = build(tmp_path, script("MOVE_BLOCK/3", ("0 0 0", 1)), params="",
                objects="1 4 100 600 0 0.5")
    try:
        run(net, 1)
        ranges, colours = net.output("R.RANGE_MAP"), net.output("R.RANGE_COLOR")
        assert ranges[16] == 1600 and ranges[0] == 100 and ranges[24] == 100
        assert ranges[8] == pytest.approx(500 - 25) and colours[8] == pytest.approx(0.5)
        assert colours[16] == 0
        assert net.output("R.VIEW_FIELD").tolist() == [550, 100]
        assert net.output("R.BLOCKS_IN_VIEW").tolist() == [[0] * 6] * 50   # 500 from it
    finally:
        net.close()
    net = build(tmp_path, script("MOVE_BLOCK/3", ("0 0 0", 1)), params="",
                objects="1 4 100 600 0 0.5; 0 0 0 0 0 0")
    try:
        run(net, 1)
        assert net.output("R.RANGE_MAP")[8] == pytest.approx(475)
        blocks = net.output("R.BLOCKS")
        assert blocks[0].tolist() == pytest.approx([4, 100, 600, 0, 0.5, 0])
        # the empty rows as Ikaros 2 writes them: -99999 in the first 100 values and in the
        # first two places of every row
        assert blocks[1:16].tolist() == [[-99999] * 6] * 15
        assert blocks[16].tolist() == [-99999] * 4 + [0, 0]
        assert blocks[17:].tolist() == [[-99999] * 2 + [0] * 4] * 33
    finally:
        net.close()


def test_the_options_for_empty_rows_and_even_sectors(tmp_path):
    """empty_rows="whole": -99999 in every place of an empty row. range_sectors="even":
    32 equal sectors. From (100, 100) facing 0.7 rad, sector 0 spans the directions
    0.7 - pi .. 0.7 - pi + 2 pi / 32 (about -2.44 .. -2.25 rad), where the floor (y = 0)
    is nearest at -2.25: 100 mm down and ceil(100 tan(0.674)) = 80 mm along; sector 3 spans
    about -3.03 .. -2.83 rad, where the left wall is nearest at 12 mm off its normal. In
    Ikaros 2 the truncation moves the directions just clockwise of straight left into
    sector 3 (the left wall 1 mm off its normal) and shifts sectors 0-2 by one (the golden
    file: sector 0 is 56 mm off the floor's normal)."""
    net = build(tmp_path, script("MOVE_BLOCK/3", ("0 0 0", 1)), objects="0 0 0 0 0 0",
                params='start="100 100 0.7" empty_rows="whole" range_sectors="even"')
    try:
        run(net, 1)
        assert net.output("R.BLOCKS").tolist() == [[-99999] * 6] * 50
        ranges = net.output("R.RANGE_MAP")
        assert ranges[0] == pytest.approx(np.hypot(100, 80))
        assert ranges[3] == pytest.approx(np.hypot(100, 12))
    finally:
        net.close()
    net = build(tmp_path, script("MOVE_BLOCK/3", ("0 0 0", 1)), objects="0 0 0 0 0 0",
                params='start="100 100 0.7"')
    try:
        run(net, 1)
        ranges = net.output("R.RANGE_MAP")
        assert ranges[0] == pytest.approx(np.hypot(100, 56))
        assert ranges[3] == pytest.approx(np.hypot(100, 1))
    finally:
        net.close()


def test_transforms_draw_the_scene_in_metres(tmp_path):
    net = build(tmp_path, script("MOVE_BLOCK/3", ("2 500 500", 2)))
    try:
        run(net, 2)
        t = net.output("R.TRANSFORMS")
        assert t.shape == (5 + 3, 16)
        body = t[0].reshape(4, 4)
        assert body[:3, 3].tolist() == pytest.approx([1.3, 0.225, 0.06])
        assert body[3].tolist() == [0, 0, 0, 1]
        block2 = t[5 + 1].reshape(4, 4)                          # moved by MOVE_BLOCK
        assert block2[:3, 3].tolist() == pytest.approx([0.5, 0.5, 0.025])
        assert np.diag(block2)[:3].tolist() == pytest.approx([0.05, 0.05, 0.05])
        shoulder_to_elbow = t[1].reshape(4, 4)
        assert np.linalg.norm(shoulder_to_elbow[:3, 0]) == pytest.approx(0.15, abs=1e-6)
    finally:
        net.close()


def test_objects_not_in_rows_of_six_are_warned_about(tmp_path):
    net = build(tmp_path, script("MOVE_BLOCK/3", ("0 0 0", 1)), objects="1 2 3 4")
    try:
        run(net, 1)
        warnings = [m for (_, level, where, m) in net.log if where == "R" and level == 5]
        assert len(warnings) == 1 and "not whole rows of 6" in warnings[0]
        assert net.output("R.OBJECTS_OUT").tolist() == [1, 2, 3, 4]
        assert net.output("R.TRANSFORMS").shape == (5, 16)
    finally:
        net.close()


def test_the_builder_example_runs_its_plan():
    """examples/gl_robot_builder.ikg to its end: block 1 stacked on block 2, block 3 moved,
    the robot back at the charging station with a full battery, no action failed."""
    import os

    import ikaros
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
        os.path.abspath(__file__))))))
    net = ikaros.load(os.path.join(root, "examples", "gl_robot_builder.ikg"))
    try:
        errors = 0.0
        for _ in range(480):                                    # the model's stop tick
            net.step()
            errors += sum(net.output(f"Robot.{e}")[0] for e in
                          ("LOCOMOTION_ERROR", "PICK_ERROR", "PLACE_ERROR"))
        assert net.tick == 480 and errors == 0
        blocks = net.output("Robot.BLOCKS")
        assert blocks[:3, :4].tolist() == [[1, 1150, 450, 50], [2, 1150, 450, 0],
                                           [3, 850, 1050, 0]]
        assert net.output("Robot.ROBOT_LOCATION")[:2].tolist() == [1400, 260]
        assert net.output("Robot.ROBOT_LOCATION")[2] == 0
        assert net.output("Robot.BATTERY_LEVEL")[0] > 0.99
    finally:
        net.close()
