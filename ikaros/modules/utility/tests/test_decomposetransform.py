"""Tests of the DecomposeTransform module: decomposition="corrected", and Ikaros 2's (golden-v2
DecomposeTransform: the diagonal as scale, angles in radians from the unscaled matrix)."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load


def _rot(ax, ay, az):
    cx, sx, cy, sy, cz, sz = np.cos(ax), np.sin(ax), np.cos(ay), np.sin(ay), np.cos(az), \
        np.sin(az)
    rx = np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]])
    ry = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    rz = np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]])
    return rz @ ry @ rx


def _matrix(t, angles, s):
    m = np.eye(4)
    m[:3, :3] = _rot(*angles) @ np.diag(s)
    m[:3, 3] = t
    return m


def _data(matrices, rows=False):
    flat = [" ".join(f"{v:.9g}" for v in m.reshape(-1)) for m in matrices]
    return "; ".join(flat) if rows else " ".join(flat)


def _load(tmp_path, data, attrs='decomposition="corrected"'):
    return load(tmp_path,
                f'<module class="Constant" name="C" data="{data}"/>\n'
                f'<module class="DecomposeTransform" name="D" {attrs}/>\n'
                '<connection source="C.OUTPUT" target="D.INPUT" delay="0"/>')


def test_translation_rotation_and_scale_of_two_matrices_in_one_row(tmp_path):
    a = _matrix([1, 2, 3], np.radians([10, 20, 30]), [1, 2, 3])
    b = _matrix([-4, 0, 0.5], np.radians([-45, 60, 170]), [0.5, 0.5, 0.5])
    net = _load(tmp_path, _data([a, b]))
    try:
        for _ in range(2):
            net.step()
            assert net.output("D.TRANSLATION").shape == (2, 3)
            assert np.allclose(net.output("D.TRANSLATION"), [[1, 2, 3], [-4, 0, 0.5]])
            assert np.allclose(net.output("D.ROTATION"), [[10, 20, 30], [-45, 60, 170]],
                               atol=1e-3)
            assert np.allclose(net.output("D.SCALE"), [[1, 2, 3], [0.5, 0.5, 0.5]],
                               atol=1e-5)
    finally:
        net.close()


def test_radians_and_a_matrix_per_row(tmp_path):
    a = _matrix([0, 0, 0], [0.1, -0.2, 0.3], [1, 1, 1])
    net = _load(tmp_path, _data([a, np.eye(4)], rows=True),
                'use_degrees="no" decomposition="corrected"')
    try:
        net.step()
        assert np.allclose(net.output("D.ROTATION"), [[0.1, -0.2, 0.3], [0, 0, 0]], atol=1e-5)
        assert np.allclose(net.output("D.SCALE"), 1, atol=1e-6)
    finally:
        net.close()


def test_gimbal_lock_puts_the_rotation_in_z(tmp_path):
    a = _matrix([0, 0, 0], np.radians([0, 90, 40]), [1, 1, 1])
    net = _load(tmp_path, _data([a]))
    try:
        net.step()
        rot = net.output("D.ROTATION")[0]
        assert np.allclose(rot, [0, 90, 40], atol=1e-2)
        assert np.allclose(_rot(*np.radians(rot)), a[:3, :3], atol=1e-5)
    finally:
        net.close()


def test_size_not_a_multiple_of_16_is_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="multiple of 16"):
        _load(tmp_path, "1 2 3")


def test_ikaros_2_scale_is_the_diagonal_and_angles_are_radians(tmp_path):
    angles = np.radians([10, 20, 30])
    a = _matrix([1, 2, 3], angles, [1, 1, 1])
    b = _matrix([0, 0, 0], [0, 0, np.pi / 2], [1, 1, 1])       # golden-v2 "defaults"
    net = _load(tmp_path, _data([a, b]), "")
    with net:
        net.step()
        assert np.allclose(net.output("D.TRANSLATION"), [[1, 2, 3], [0, 0, 0]])
        assert np.allclose(net.output("D.ROTATION"), [angles, [0, 0, np.pi / 2]], atol=1e-5)
        assert np.allclose(net.output("D.SCALE"), [np.diag(a)[:3], np.diag(b)[:3]],
                           atol=1e-6)
