"""Tests of the Ikaros 3 PlanarArm (dialect 3, MODULES-V3 §26), in worlds of our own."""
import math

import numpy as np

from ikaros.testing import load_body as load

EMPTY = ('circle_obstacle_count="0" line_obstacle_count="0" movable_object="250, 250, 10" '
         'base_position="150, 150" link_lengths="50, 40" initial_joint_angles="0.2, 0.3" '
         'joint_min="-3, -3" joint_max="3, 3"')


def _net(tmp_path, attrs, command=None, gripper=None):
    body = f'<module class="PlanarArm" name="A" {attrs}/>'
    for port, data in (("JOINT_COMMAND", command), ("GRIPPER", gripper)):
        if data is not None:
            body += (f'<module class="Constant" name="{port}" data="{data}"/>'
                     f'<connection source="{port}.OUTPUT" target="A.{port}" delay="0"/>')
    return load(tmp_path, body, dialect="3")


def hand(angles, lengths=(50, 40), base=(150, 150)):
    """Forward kinematics: relative angles, counter-clockwise from +x."""
    points, theta, p = [np.array(base, float)], 0.0, np.array(base, float)
    for a, length in zip(angles, lengths):
        theta += a
        p = p + length * np.array([math.cos(theta), math.sin(theta)])
        points.append(p)
    return np.array(points)


def test_forward_kinematics_and_a_free_move_in_one_tick(tmp_path):
    net = _net(tmp_path, EMPTY, command="1.0 -0.4")
    try:
        assert net.output("A.JOINT_POSITIONS").shape == (3, 2)
        assert net.output("A.ARM_LINES").shape == (5, 11)
        assert net.output("A.WALLS").shape == (5, 11) and net.output("A.OBJECTS").shape == (1, 18)
        net.step()
        assert np.allclose(net.output("A.JOINT_ANGLES"), [1.0, -0.4])
        assert np.allclose(net.output("A.JOINT_POSITIONS"), hand([1.0, -0.4]), atol=1e-4)
        end = net.output("A.END_EFFECTOR")
        assert np.allclose(end, [*hand([1.0, -0.4])[-1], 0.6], atol=1e-4)
        assert net.output("A.BLOCKED")[0] == 0 and not net.output("A.OBJECT_CONTACTS").any()
        assert np.allclose(net.output("A.ARM_LINES")[0],
                           [1, 1, 150, 150, *hand([1.0, -0.4])[1], 0.12, 0.35, 0.75, 1, 6],
                           atol=1e-4)
    finally:
        net.close()


def test_a_fixed_line_blocks_the_motion(tmp_path):
    # a wall at x = 200 from y = 60 to 290: the 90-long arm swinging down to 0 hits it
    attrs = EMPTY.replace('line_obstacle_count="0"', 'line_obstacle_count="1" '
                          'line_obstacles="200, 60, 200, 290, 4"').replace(
        'initial_joint_angles="0.2, 0.3"', 'initial_joint_angles="1.5, 0"')
    net = _net(tmp_path, attrs, command="0 0")
    try:
        net.step()
        angle = net.output("A.JOINT_ANGLES")[0]
        assert net.output("A.BLOCKED")[0] == 1
        assert 0 < angle < 1.5
        # the last accepted pose keeps the arm (and gripper) clear of the wall
        assert net.output("A.JOINT_POSITIONS")[:, 0].max() < 200
        assert net.output("A.WALLS")[5, 2:6].tolist() == [200, 60, 200, 290]
    finally:
        net.close()


def test_the_arm_pushes_the_movable_object(tmp_path):
    # the object lies on the path of the link sweeping down from 0.5 to 0
    attrs = EMPTY.replace('movable_object="250, 250, 10"', 'movable_object="180, 160, 5"') \
        .replace('initial_joint_angles="0.2, 0.3"', 'initial_joint_angles="0.5, 0"')
    net = _net(tmp_path, attrs, command="0 0")
    try:
        net.step()
        assert net.output("A.BLOCKED")[0] == 0
        x, y, r, _ = net.output("A.MOVABLE_OBJECT")
        assert r == 5 and y < 160
        assert net.output("A.OBJECT_CONTACTS")[0] == 1 and net.output("A.LINK_CONTACTS")[0] == 1
        # the object is left touching the link, 3 (half its width) + 5 away from it
        assert abs(abs(y - 150) - 8) < 1e-3
    finally:
        net.close()
