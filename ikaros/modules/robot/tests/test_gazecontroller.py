"""GazeController against an independent forward kinematics (scipy rotations)."""
import math

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from ikaros.errors import ModelError
from ikaros.testing import load_body

A, B, C, D = 0.077, 0.120, 0.060, 0.060
ORIGIN = np.array([0.0, 0.0, 0.693])


def eye_rays(pan, tilt, left, right, A=A, B=B, C=C, D=D, origin=ORIGIN):
    """(position, direction) of both eyes for joint angles in radians, by composing rotations:
    pan about z, then tilt about the head's y axis (positive tilt raises the gaze), then each
    eye's pan about the head's z axis."""
    head = Rotation.from_euler("ZY", [pan, -tilt])
    axis = origin + [0, 0, A]
    rays = []
    for side, eye in ((1, left), (-1, right)):
        position = axis + head.apply([C, side * D / 2, B])
        direction = (head * Rotation.from_euler("Z", eye)).apply([1.0, 0, 0])
        rays.append((position, direction))
    return rays


def miss_distance(position, direction, target):
    """How far the target is from the ray; inf when it is behind the eye."""
    offset = np.asarray(target) - position
    along = offset @ direction
    return np.linalg.norm(offset - along * direction) if along > 0 else math.inf


def run(tmp_path, target, params="", ticks=1):
    body = (f'<module class="Constant" name="T" data="{target}"/>\n'
            f'<module class="GazeController" name="G" {params}/>\n'
            '<connection source="T.OUTPUT" target="G.INPUT" delay="0"/>')
    net = load_body(tmp_path, body)
    net.run(ticks=ticks)
    return net


TARGETS = [(0.5, 0.0, 0.89), (1.0, 0.3, 1.2), (0.4, -0.5, 0.5), (2.0, 1.5, 0.7),
           (0.3, 0.2, 1.3), (-0.5, 0.4, 0.9), (0.6, 0.05, 0.6)]


@pytest.mark.parametrize("target", TARGETS)
def test_both_eyes_look_at_the_target(tmp_path, target):
    net = run(tmp_path, " ".join(map(str, target)), 'angle_unit="radians"')
    try:
        angles = net.output("G.OUTPUT").astype(np.float64)
        for position, direction in eye_rays(*angles):
            assert miss_distance(position, direction, target) < 2e-6   # float32 angles
    finally:
        net.close()


def test_straight_ahead_at_eye_height_is_all_level_and_eyes_converge(tmp_path):
    net = run(tmp_path, "0.5 0 0.89")
    try:
        out = net.output("G.OUTPUT")
        converge = math.degrees(math.atan2(D / 2, 0.5 - C))        # eyes 0.44 m from target
        assert np.allclose(out, [0, 0, -converge, converge], atol=1e-5)
    finally:
        net.close()


def test_units_offset_and_override(tmp_path):
    target = (1.0, 0.3, 1.2)
    net = run(tmp_path, "0 0 0", 'angle_unit="tau" offset="0.5" target_override="yes" '
              'target="1.0 0.3 1.2"')
    try:
        tau = net.output("G.OUTPUT").astype(np.float64)
        for position, direction in eye_rays(*((tau - 0.5) * 2 * math.pi)):
            assert miss_distance(position, direction, target) < 1e-5
        assert abs(tau[0] - 0.5 - math.atan2(0.3, 1.0) / (2 * math.pi)) < 1e-7
    finally:
        net.close()


def test_other_head_dimensions(tmp_path):
    target = (0.7, -0.2, 0.4)
    dims = dict(A=0.05, B=0.2, C=0.1, D=0.12)
    params = " ".join(f'{k}="{v}"' for k, v in dims.items()) + ' origin="0.1 0.1 0.3" ' \
        'angle_unit="radians"'
    net = run(tmp_path, "0.7 -0.2 0.4", params)
    try:
        angles = net.output("G.OUTPUT").astype(np.float64)
        for position, direction in eye_rays(*angles, origin=np.array([0.1, 0.1, 0.3]), **dims):
            assert miss_distance(position, direction, target) < 2e-6
    finally:
        net.close()


def test_target_too_close_holds_the_angles_with_a_warning(tmp_path, capsys):
    # the tilt axis is at 0.77 m; a target 5 cm from it is inside the eye height B = 0.12
    net = run(tmp_path, "0.03 0 0.8", ticks=2)
    try:
        assert np.all(net.output("G.OUTPUT") == 0)
        assert "cannot look at" in capsys.readouterr().err
    finally:
        net.close()


def test_drawings_show_the_head_where_the_kinematics_put_it(tmp_path):
    target = (1.0, 0.3, 1.2)
    net = run(tmp_path, "1.0 0.3 1.2", 'angle_unit="radians"')
    try:
        angles = net.output("G.OUTPUT").astype(np.float64)
        (eye_l, dir_l), (eye_r, dir_r) = eye_rays(*angles)
        top = net.output("G.VIEW_TOP")
        side = net.output("G.VIEW_SIDE")
        assert top.shape == (14, 4) and side.shape == (9, 4)
        assert np.allclose(top[4], [*eye_l[:2], *eye_r[:2]], atol=1e-6)      # eye baseline
        assert np.allclose(top[5], [*eye_l[:2], *(eye_l + 0.04 * dir_l)[:2]], atol=1e-6)
        assert np.allclose(top[7], [*eye_l[:2], *target[:2]], atol=1e-6)     # line of sight
        assert np.allclose(top[8], [*eye_r[:2], *target[:2]], atol=1e-6)
        middle = (eye_l + eye_r) / 2
        reach = math.hypot(*target[:2])
        side_eyes = [math.hypot(*middle[:2]), middle[2]]
        assert np.allclose(side[0], [*side_eyes, reach, target[2]], atol=1e-6)
        assert np.allclose(side[1], [0, 0.693, 0, 0.77], atol=1e-6)           # the neck
    finally:
        net.close()


def test_input_needs_three_values(tmp_path):
    with pytest.raises(ModelError, match="needs 3"):
        run(tmp_path, "1 2")
