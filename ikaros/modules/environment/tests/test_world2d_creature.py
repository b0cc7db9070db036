"""Tests of World2D's creature world (Ikaros 3's interface, this project's reading): the
differential drive, blocking, contacts, whiskers, odour, reinforcement and editing, with
expected values from the kinematics and geometry written out here."""
import math

import numpy as np
import pytest

from ikaros.testing import load_body as load

EMPTY = 'food="0" aversive="0" walls="0"'


def world(tmp_path, motor=None, attrs=EMPTY, dialect="3"):
    body = f'<module class="World2D" name="W" {attrs}/>'
    if motor is not None:
        body += (f'<module class="Constant" name="M" data="{motor}"/>'
                 '<connection source="M.OUTPUT" target="W.MOTOR" delay="0"/>')
    return load(tmp_path, body, **({"dialect": dialect} if dialect else {}))


def drive(x, y, h, left, right, wheel_radius=1.0, wheel_base=6.0):
    """One tick of a differential drive along its arc."""
    dl, dr = 2 * math.pi * wheel_radius * left, 2 * math.pi * wheel_radius * right
    d, turn = (dl + dr) / 2, (dr - dl) / wheel_base
    if turn == 0:
        return x + d * math.cos(h), y + d * math.sin(h), h
    r = d / turn
    return x + r * (math.sin(h + turn) - math.sin(h)), \
        y - r * (math.cos(h + turn) - math.cos(h)), h + turn


def test_straight_and_turning_drive(tmp_path):
    net = world(tmp_path, "0.05 0.1")
    try:
        x, y, h = 150.0, 150.0, 0.0
        for _ in range(30):
            net.step()
            x, y, h = drive(x, y, h, 0.05, 0.1)
            h = (h + math.pi) % (2 * math.pi) - math.pi
            assert np.allclose(net.output("W.POSE"), [x, y, h], atol=1e-4)
        creature = net.output("W.CREATURE")
        assert np.allclose(creature[:6], [x, y, h, 4, 10, math.pi / 4], atol=1e-4)
    finally:
        net.close()


def test_a_turn_on_one_wheel_comes_back_round(tmp_path):
    # one wheel at 0.1 rotations: 0.2 pi per tick, a turn of 0.2 pi / 6: round in 60 ticks
    net = world(tmp_path, "0 0.1")
    try:
        net.run(ticks=60)
        assert np.allclose(net.output("W.POSE"), [150, 150, 0], atol=1e-3)
    finally:
        net.close()


def test_motor_is_clipped_to_max_motor_rpt(tmp_path):
    net = world(tmp_path, "1 1", EMPTY + ' max_motor_rpt="0.2" wheel_radius="2"')
    try:
        net.step()
        assert np.allclose(net.output("W.POSE"), [150 + 2 * math.pi * 2 * 0.2, 150, 0])
    finally:
        net.close()


WALL = 'food="0" aversive="0" walls="1, 200, 100, 200, 200, 0.2, 0.2, 0.2, 1, 2, 1"'


def test_a_wall_stops_the_creature_touching_it(tmp_path):
    net = world(tmp_path, "0.25 0.25", WALL)
    try:
        for _ in range(40):
            net.step()
        # the wall's face is at 200 - 1, the body's radius 4
        assert net.output("W.POSE")[0] == pytest.approx(195, abs=1e-4)
        assert net.output("W.CONTACT").tolist() == [1, 1]        # straight ahead: both
        assert net.output("W.WALLS").tolist()[0] == pytest.approx(
            [1, 1, 200, 100, 200, 200, 0.2, 0.2, 0.2, 1, 2])
    finally:
        net.close()


def test_whiskers_measure_the_distance_to_the_wall(tmp_path):
    net = world(tmp_path, "0.25 0.25", WALL.replace("200, 100, 200, 200", "160, 100, 160, 200"))
    try:
        net.step()            # x = 150 + 2 pi 0.25 = 151.57
        x = 150 + 2 * math.pi * 0.25
        root = x + 4 * math.cos(math.pi / 4)
        s = (159 - root) / math.cos(math.pi / 4)         # along the whisker to the face
        expected = max(0.0, 1 - s / 10)
        assert expected > 0
        assert np.allclose(net.output("W.WHISKERS"), [expected, expected], atol=1e-5)
        assert net.output("W.CONTACT").tolist() == [0, 0]
    finally:
        net.close()


def test_odour_and_reward_of_food(tmp_path):
    food = 'food="1, 160, 150, 5, 2, 0.2, 0.7, 0.2, 0, 0, 1, 0, 0, 0, 0, 0, 0.5" ' \
           'aversive="2, 150, 165, 6, -1.5, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0" walls="0"'
    net = world(tmp_path, None, food + ' odour_decay="0.05"')
    try:
        net.step()
        for row, side in enumerate((1, -1)):
            a = side * math.pi / 4
            root = np.array([150 + 4 * math.cos(a), 150 + 4 * math.sin(a)])
            d = np.hypot(*(root - [160, 150])) - 5
            expected = np.zeros(8)
            expected[1], expected[7] = math.exp(-0.05 * d), 0.5 * math.exp(-0.05 * d)
            assert np.allclose(net.output("W.ODOUR")[row], expected, atol=1e-6)
        # the food (radius 5 at 10 from the centre) is 1 away from the body: no reward yet
        assert net.output("W.REWARD")[0] == 0
        objects = net.output("W.OBJECTS")
        assert objects.shape == (2, 18)
        assert objects[0].tolist() == pytest.approx(
            [1, 1, 160, 150, 5, 2, 0.2, 0.7, 0.2, 0, 0, 1, 0, 0, 0, 0, 0, 0.5])
        assert objects[1][:2].tolist() == [2, 2]
    finally:
        net.close()
    net = world(tmp_path, "0.1 0.1", food)      # food is not solid: the creature reaches it
    try:
        net.step()                              # x = 150.63: 0.37 from the food's edge
        assert net.output("W.REWARD")[0] == 0
        net.step()                              # x = 151.26: over it
        assert net.output("W.REWARD")[0] == 2 and net.output("W.REINFORCEMENT")[0] == 2
    finally:
        net.close()


def test_touching_an_aversive_object_punishes(tmp_path):
    aversive = 'food="0" walls="0" creature_heading="1.5707963" ' \
               'aversive="2, 150, 165, 6, -1.5, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0"'
    net = world(tmp_path, "0.25 0.25", aversive)
    try:
        net.run(ticks=5)
        assert net.output("W.POSE")[1] == pytest.approx(165 - 6 - 4, abs=1e-4)
        assert net.output("W.PUNISHMENT")[0] == 1.5
        assert net.output("W.REINFORCEMENT")[0] == -1.5
    finally:
        net.close()


def test_editing_adds_and_removes_objects_and_walls(tmp_path):
    net = world(tmp_path, None, 'edit_tool="2" edit_type="1" edit_value="-2" '
                                'edit_color="0.1, 0.2, 0.3"')
    try:
        assert [net.output(f"W.{n}")[0] for n in ("EDIT_OBJECT_ENABLE", "EDIT_WALL_ENABLE",
                                                  "EDIT_COLOR_ENABLE")] == [0, 1, 0]
        assert net.parameter("W.food").shape == (2, 17)
        net.command("W", "add_object", 100, 100)          # edit_type 1: aversive
        assert net.parameter("W.aversive").shape == (6, 17)
        assert net.parameter("W.aversive")[-1][:9].tolist() == pytest.approx(
            [14, 100, 100, 8, -2, 0.1, 0.2, 0.3, 1])
        net.command("W", "remove_object", 72, 71)          # inside the first food
        assert net.parameter("W.food").shape == (1, 17)
        net.command("W", "add_wall", 10, 10, value=[40, 10])
        assert net.parameter("W.walls").shape == (7, 11)
        net.command("W", "remove_wall", 20, 12)
        assert net.parameter("W.walls").shape == (6, 11)
    finally:
        net.close()


def test_an_ikaros2_file_gets_the_creature_when_asked(tmp_path):
    net = world(tmp_path, "0.1 0.1", EMPTY + ' simulation="creature" wheel_base="6"',
                dialect=None)
    try:
        net.step()
        assert np.allclose(net.output("W.POSE"), [150 + 0.2 * math.pi, 150, 0])
    finally:
        net.close()


def test_the_creature_example_finds_the_food():
    import os
    import ikaros
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
        os.path.abspath(__file__))))))
    net = ikaros.load(os.path.join(root, "examples", "modules", "World2D_creature_example.ikg"))
    try:
        reward = []
        for _ in range(400):
            net.step()
            reward.append(float(net.output("World.REWARD")[0]))
            assert net.output("World.PUNISHMENT")[0] == 0
    finally:
        net.close()
    assert reward.index(1.0) == 166 and all(r == 1 for r in reward[166:])
