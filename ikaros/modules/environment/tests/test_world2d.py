"""Tests of the World2D module: an elastic frictionless collision conserves momentum and
energy (and gives the textbook velocities), range sensors report known distances, the
differential drive follows its kinematics, walls stop the robot, and damping works."""
import math

import numpy as np
import pytest

import pymunk  # noqa: F401  (the physics extra; part of the test extras)

from ikaros.testing import load_body as load      # noqa: E402


def world(tmp_path, move=None, **params):
    attrs = " ".join(f'{k}="{v}"' for k, v in params.items())
    body = f'<module class="World2D" name="W" {attrs}/>'
    if move is not None:
        body += (f'<module class="Constant" name="M" data="{move}"/>'
                 '<connection source="M.OUTPUT" target="W.MOVE" delay="0"/>')
    return load(tmp_path, body)


ELASTIC = dict(elasticity=1, friction=0, damping=1, robot_x=0.3, robot_y=0.3)


def test_head_on_elastic_collision(tmp_path):
    # m1 = 1 at 1 m/s hits m2 = 2 at rest: v1' = (m1-m2)/(m1+m2) = -1/3, v2' = 2/3
    net = world(tmp_path, objects="1.5 1.5 0.1 1 1 0; 2.5 1.5 0.1 2 0 0", **ELASTIC)
    try:
        p0, e0 = net.output("W.MOMENTUM"), net.output("W.ENERGY")
        assert np.allclose(p0, [1, 0]) and e0[0] == pytest.approx(0.5)
        net.run(ticks=150)                  # they meet at 0.8 s; no wall is reached by 1.5 s
        v = net.output("W.OBJECT_VELOCITIES")
        assert np.allclose(v[:, :2], [[-1 / 3, 0], [2 / 3, 0]], atol=1e-3)
        assert np.allclose(net.output("W.MOMENTUM"), p0, atol=1e-3)
        assert net.output("W.ENERGY")[0] == pytest.approx(e0[0], rel=1e-3)
    finally:
        net.close()


def test_oblique_elastic_collision_conserves_momentum_and_energy(tmp_path):
    net = world(tmp_path, objects="1.5 1.4 0.1 1 1.5 0.2; 2.5 1.5 0.15 3 -0.5 0", **ELASTIC)
    try:
        v0 = net.output("W.OBJECT_VELOCITIES")
        masses = np.array([1.0, 3.0])
        p0 = masses @ v0[:, :2]
        e0 = 0.5 * masses @ (v0[:, :2] ** 2).sum(axis=1)
        assert np.allclose(net.output("W.MOMENTUM"), p0)
        net.run(ticks=80)
        v = net.output("W.OBJECT_VELOCITIES")
        pos = net.output("W.OBJECTS")
        assert not np.allclose(v, v0, atol=0.05)                       # they did collide
        assert np.all(pos[:, 0] > 0.5) and np.all(pos[:, 0] < 3.5)     # far from the walls
        assert np.all(pos[:, 1] > 0.5) and np.all(pos[:, 1] < 2.5)
        # the objects' own momentum and energy, computed here from their velocities
        assert np.allclose(masses @ v[:, :2], p0, atol=2e-3)
        assert 0.5 * masses @ (v[:, :2] ** 2).sum(axis=1) == pytest.approx(e0, rel=2e-3)
        assert np.allclose(net.output("W.MOMENTUM"), p0, atol=2e-3)
        assert net.output("W.ENERGY")[0] == pytest.approx(e0, rel=2e-3)
    finally:
        net.close()


def test_inelastic_collision_loses_energy_but_keeps_momentum(tmp_path):
    net = world(tmp_path, objects="1.5 1.5 0.1 1 1 0; 2.5 1.5 0.1 1 0 0",
                **{**ELASTIC, "elasticity": 0})
    try:
        net.run(ticks=150)
        v = net.output("W.OBJECT_VELOCITIES")
        assert np.allclose(v[:, :2], [[0.5, 0], [0.5, 0]], atol=1e-3)     # they move together
        assert np.allclose(net.output("W.MOMENTUM"), [1, 0], atol=1e-3)
        assert net.output("W.ENERGY")[0] == pytest.approx(0.25, rel=1e-3)
    finally:
        net.close()


def test_range_sensors_report_known_distances(tmp_path):
    # robot (radius 0.15) at (1, 1.5) facing +x in a 4 x 3 arena; an object of radius 0.1
    # at (2.5, 1.5) ahead; a box from (0.2, 0.2) to (1.8, 0.6) below
    net = world(tmp_path, robot_x=1, robot_y=1.5, robot_heading=0, sensor_range=5,
                sensor_angles=f"0 {math.pi / 2} {math.pi} {-math.pi / 2} {math.pi / 4}",
                objects="2.5 1.5 0.1 1", obstacles="0.2 0.2 1.8 0.6")
    try:
        ranges = net.output("W.RANGES")
        diagonal = (3 - 1.5) * math.sqrt(2) - 0.15       # up-right: the top wall at y = 3
        expected = [2.4 - 1.15,        # the object's near side, from the robot's rim
                    3 - 1.5 - 0.15,    # top wall
                    1 - 0.15,          # left wall
                    1.5 - 0.6 - 0.15,  # top of the box
                    diagonal]
        assert np.allclose(ranges, expected, atol=1e-4)
        points = net.output("W.RANGE_POINTS")
        assert np.allclose(points, [[2.4, 1.5], [1, 3], [0, 1.5], [1, 0.6], [2.5, 3]],
                           atol=1e-4)
        assert net.output("W.COLLISION")[0] == 0
        walls = net.output("W.WALLS")
        assert walls.shape == (8, 4)
        assert np.allclose(walls[:4], [[0, 0, 4, 0], [4, 0, 4, 3], [4, 3, 0, 3], [0, 3, 0, 0]])
        assert np.allclose(walls[4], [0.2, 0.2, 1.8, 0.2])
    finally:
        net.close()
    # nothing within range: the sensor reports sensor_range
    net = world(tmp_path, robot_x=1, robot_y=1.5, sensor_range=0.5, sensor_angles="0 3.14159",
                objects="")
    try:
        assert np.allclose(net.output("W.RANGES"), [0.5, 0.5])
        assert net.output("W.OBJECTS").shape == (1, 4)          # no objects: one row of 0
        assert np.all(net.output("W.OBJECTS") == 0)
    finally:
        net.close()


def test_differential_drive_kinematics(tmp_path):
    # equal wheels at 0.4 m/s for 0.5 s: 0.2 m along the heading (30 degrees), no turn
    h = math.pi / 6
    net = world(tmp_path, move="0.4 0.4", robot_x=1, robot_y=1, robot_heading=h, damping=1,
                objects="", time_step=0.01)
    try:
        net.run(ticks=50)
        assert np.allclose(net.output("W.POSE"), [1 + 0.2 * math.cos(h), 1 + 0.2 * math.sin(h),
                                                  h], atol=2e-3)
        assert np.allclose(net.output("W.VELOCITY"), [0.4 * math.cos(h), 0.4 * math.sin(h), 0],
                           atol=1e-3)
    finally:
        net.close()
    # opposite wheels turn on the spot: (right - left) / wheel_base = 0.6 / 0.3 = 2 rad/s
    net = world(tmp_path, move="-0.3 0.3", robot_x=2, robot_y=1.5, wheel_base=0.3, damping=1,
                objects="")
    try:
        net.run(ticks=50)                   # 0.5 s at tick_duration 0.01
        pose = net.output("W.POSE")
        assert np.allclose(pose[:2], [2, 1.5], atol=1e-3)
        assert pose[2] == pytest.approx(1.0, abs=2e-2)
    finally:
        net.close()
    # wheel speeds are clipped to max_speed
    net = world(tmp_path, move="5 5", max_speed=0.5, objects="", damping=1)
    try:
        net.step()
        assert net.output("W.VELOCITY")[0] == pytest.approx(0.5, abs=1e-3)
    finally:
        net.close()


def test_walls_stop_the_robot(tmp_path):
    net = world(tmp_path, move="1 1", robot_x=3, robot_y=1.5, objects="", damping=1)
    try:
        net.run(ticks=200)                  # 2 s at 1 m/s would take it to x = 5
        x = net.output("W.POSE")[0]
        assert 3.8 < x <= 4 - 0.15 + 0.01
        assert net.output("W.COLLISION")[0] == 1
        assert net.output("W.RANGES")[2] == pytest.approx(0, abs=0.02)   # the sensor ahead
    finally:
        net.close()


def test_damping_and_reset(tmp_path):
    # damping 0.5: a free body keeps half its velocity per second
    net = world(tmp_path, objects="2 1.5 0.1 1 0.2 0", damping=0.5)
    try:
        net.run(ticks=100)
        assert net.output("W.OBJECT_VELOCITIES")[0, 0] == pytest.approx(0.1, rel=1e-2)
        net.command("W", "reset")
        assert np.allclose(net.output("W.OBJECTS")[0], [2, 1.5, 0, 0.1])
        assert np.allclose(net.output("W.OBJECT_VELOCITIES")[0], [0.2, 0, 0])
    finally:
        net.close()


def test_pushing_an_object(tmp_path):
    net = world(tmp_path, move="0.5 0.5", robot_x=1, robot_y=1.5, objects="1.6 1.5 0.1 0.2",
                friction=0, damping=0.9)
    try:
        net.run(ticks=150)
        obj = net.output("W.OBJECTS")[0]
        assert obj[0] > 1.9                 # pushed ahead of the robot
        assert net.output("W.POSE")[0] < obj[0] - 0.2
    finally:
        net.close()
