"""Tests of the Fuse module."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load


def rot_z(a, tx=0.0, ty=0.0, tz=0.0):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0, tx], [s, c, 0, ty], [0, 0, 1, tz], [0, 0, 0, 1]])


def text(rows):
    return "; ".join(" ".join(repr(float(v)) for v in np.ravel(r)) for r in rows)


def model(m1, o1, f1, m2, o2, f2):
    return (f'<module class="Constant" name="M1" data="{text(m1)}"/>'
            f'<module class="Constant" name="O1" data="{" ".join(map(str, o1))}"/>'
            f'<module class="Constant" name="F1" data="{" ".join(map(str, f1))}"/>'
            f'<module class="Constant" name="M2" data="{text(m2)}"/>'
            f'<module class="Constant" name="O2" data="{" ".join(map(str, o2))}"/>'
            f'<module class="Constant" name="F2" data="{" ".join(map(str, f2))}"/>'
            '<module class="Fuse" name="Fu"/>'
            + "".join(f'<connection source="{s}{k}.OUTPUT" target="Fu.{t}_{k}" delay="0"/>'
                      for k in (1, 2) for s, t in (("M", "MATRIX"), ("O", "OBJECT_ID"),
                                                   ("F", "FRAME_ID"))))


def test_averages_matching_ids_and_sorts(tmp_path):
    a, b = rot_z(0.2, 1, 2, 3), rot_z(0.4, 3, 2, 1)
    other = rot_z(1.0, 5, 5, 5)
    invalid = np.zeros((4, 4))
    net = load(tmp_path, model([other, a, invalid], [7, 2, 1], [0, 1, 1],
                               [b, rot_z(0.0)], [2, 2], [1, 3]))
    try:
        assert net.output("Fu.MATRIX").shape == (5, 16)
        for _ in range(2):
            net.step()
            ids = net.output("Fu.OBJECT_ID")
            frames = net.output("Fu.FRAME_ID")
            assert np.array_equal(ids, [2, 2, 7, 0, 0])
            assert np.array_equal(frames, [1, 3, 0, 0, 0])
            m = net.output("Fu.MATRIX").reshape(5, 4, 4)
            # the average of two turns about z by 0.2 and 0.4, made a rotation again, is the
            # turn by 0.3; the translations average
            assert np.allclose(m[0], rot_z(0.3, 2, 2, 2), atol=1e-5)
            assert np.allclose(m[1], rot_z(0.0), atol=1e-6)
            assert np.allclose(m[2], other, atol=1e-6)
            assert np.all(m[3:] == 0)
    finally:
        net.close()


def test_rotation_part_is_orthonormal_with_determinant_one(tmp_path):
    rng = np.random.default_rng(0)
    noisy = [rot_z(0.5) + np.pad(rng.normal(0, 0.05, (3, 3)), ((0, 1), (0, 1)))
             for _ in range(2)]
    net = load(tmp_path, model(noisy, [1, 1], [0, 0], [rot_z(2.0)], [1], [0]))
    try:
        net.step()
        m = net.output("Fu.MATRIX").reshape(3, 4, 4)
        r = m[0, :3, :3].astype(np.float64)
        assert np.allclose(r @ r.T, np.eye(3), atol=1e-5)
        assert np.isclose(np.linalg.det(r), 1, atol=1e-5)
        # independent: the nearest rotation (polar factor) of the average, by SVD in the test
        avg = (noisy[0] + noisy[1] + rot_z(2.0))[:3, :3] / 3
        u, _, vt = np.linalg.svd(avg)
        assert np.allclose(r, u @ vt, atol=1e-5)
        assert np.array_equal(net.output("Fu.OBJECT_ID"), [1, 0, 0])
    finally:
        net.close()


def test_nothing_valid_gives_zeros(tmp_path):
    z = np.zeros((4, 4))
    net = load(tmp_path, model([z], [3], [1], [z], [4], [1]))
    try:
        net.step()
        assert np.all(net.output("Fu.MATRIX") == 0)
        assert np.all(net.output("Fu.OBJECT_ID") == 0)
    finally:
        net.close()


def test_matrix_size_must_be_a_multiple_of_16(tmp_path):
    with pytest.raises(ikaros.ModelError):
        load(tmp_path, '<module class="Constant" name="M" data="1 2 3"/>'
             '<module class="Constant" name="I" data="1"/>'
             '<module class="Fuse" name="Fu" no_of_inputs="1"/>'
             '<connection source="M.OUTPUT" target="Fu.MATRIX_1"/>'
             '<connection source="I.OUTPUT" target="Fu.OBJECT_ID_1"/>'
             '<connection source="I.OUTPUT" target="Fu.FRAME_ID_1"/>')
