"""Tests of the RotationConverter module."""

import numpy as np
import pytest

import ikaros
from ikaros.module import WARNING
from ikaros.testing import load_body as load


def rx(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def ry(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def rz(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def pose(x, y, z, ax, ay, az):
    """4x4 transform from a position and angles in radians: R = Rz Ry Rx."""
    m = np.eye(4)
    m[:3, :3] = rz(az) @ ry(ay) @ rx(ax)
    m[:3, 3] = x, y, z
    return m


def rodrigues(axis, angle):
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(angle) * kx + (1 - np.cos(angle)) * kx @ kx


def convert(tmp_path, data, ticks=1, **attrs):
    text = " ".join(f'{k}="{v}"' for k, v in attrs.items())
    net = load(tmp_path, f'<module class="Constant" name="C" data="{data}"/>'
                         f'<module class="RotationConverter" name="R" {text}/>'
                         '<connection source="C.OUTPUT" target="R.INPUT" delay="0"/>')
    try:
        net.run(ticks=ticks)
        return net.output("R.OUTPUT"), [e for e in net.log if e[1] == WARNING]
    finally:
        net.close()


def test_default_copies_a_position(tmp_path):
    out, _ = convert(tmp_path, "1 2 3")
    assert out.shape == (3,) and out.dtype == np.float32
    assert np.array_equal(out, [1, 2, 3])


def test_xyz_to_matrix_hand_worked(tmp_path):
    out, _ = convert(tmp_path, "1 2 3", output_format="matrix")
    assert out.shape == (16,)
    assert np.array_equal(out, [1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1])


def test_yaw_90_degrees_hand_worked(tmp_path):
    out, _ = convert(tmp_path, "1 2 3 0 0 90", input_format="xyzaxayaz",
                     output_format="matrix")
    assert np.allclose(out, [0, -1, 0, 1, 1, 0, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1], atol=1e-6)
    out, _ = convert(tmp_path, "0 0 90", input_format="axayaz", output_format="quaternion")
    assert np.allclose(out, [0, 0, np.sqrt(0.5), np.sqrt(0.5)], atol=1e-6)


@pytest.mark.parametrize("unit, scale", [("degrees", 180 / np.pi), ("radians", 1.0),
                                         ("tau", 1 / (2 * np.pi))])
def test_angles_to_matrix_rows_match_numpy(tmp_path, unit, scale):
    poses = np.array([[0.5, -1, 2, 0.3, -0.7, 2.5], [0, 0, 0, -2.0, 1.2, -0.4],
                      [3, 2, 1, 0, 0, 0]])
    data = "; ".join(" ".join(f"{v:.9g}" for v in np.r_[p[:3], p[3:] * scale]) for p in poses)
    out, _ = convert(tmp_path, data, input_format="xyzaxayaz", output_format="matrix",
                     angle_unit=unit)
    assert out.shape == (3, 16)
    for row, p in zip(out, poses):
        assert np.allclose(row, pose(*p).reshape(-1), atol=1e-5)


def test_matrix_to_angles_round_trip(tmp_path):
    p = [1, 2, 3, 0.4, -0.9, 2.8]
    data = " ".join(f"{v:.9g}" for v in pose(*p).reshape(-1))
    out, _ = convert(tmp_path, data, input_format="matrix", output_format="xyzaxayaz",
                     angle_unit="radians")
    assert np.allclose(out, p, atol=1e-5)
    out, _ = convert(tmp_path, data, input_format="matrix", output_format="xyz")
    assert np.allclose(out, [1, 2, 3])


def test_a_4x4_matrix_input_is_one_pose(tmp_path):
    m = pose(4, 5, 6, 0, 0, np.pi / 2)
    data = "; ".join(" ".join(f"{v:.9g}" for v in row) for row in m)
    out, _ = convert(tmp_path, data, input_format="matrix", output_format="xyzaxayaz")
    assert out.shape == (6,)
    assert np.allclose(out, [4, 5, 6, 0, 0, 90], atol=1e-4)


def test_quaternion_to_matrix_matches_rodrigues(tmp_path):
    axis, angle = np.array([1.0, -2.0, 0.5]), 1.3
    k = axis / np.linalg.norm(axis)
    q = np.r_[k * np.sin(angle / 2), np.cos(angle / 2)] * 3     # not normalised on purpose
    out, _ = convert(tmp_path, " ".join(f"{v:.9g}" for v in q), input_format="quaternion",
                     output_format="matrix")
    expected = np.eye(4)
    expected[:3, :3] = rodrigues(axis, angle)
    assert np.allclose(out, expected.reshape(-1), atol=1e-5)


def test_angles_to_quaternion_and_back(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="A" outputsize_x="3" outputsize_y="4" '
                         'min="-80" max="80" seed="6"/>'
                         '<module class="RotationConverter" name="Q" input_format="axayaz" '
                         'output_format="quaternion"/>'
                         '<module class="RotationConverter" name="B" input_format="quaternion" '
                         'output_format="axayaz"/>'
                         '<connection source="A.OUTPUT" target="Q.INPUT" delay="0"/>'
                         '<connection source="Q.OUTPUT" target="B.INPUT" delay="0"/>',
               dialect=2)        # Ikaros 2 computes quaternions (Ikaros 3 gives zeros)
    try:
        for _ in range(3):
            net.step()
            a = net.output("A.OUTPUT")
            q = net.output("Q.OUTPUT")
            assert q.shape == (4, 4)
            assert np.allclose(np.linalg.norm(q, axis=1), 1, atol=1e-6)
            assert np.all(q[:, 3] >= 0)
            for angles, quat in zip(np.radians(a.astype(np.float64)), q):
                x, y, z, w = quat
                r = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                              [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                              [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])
                assert np.allclose(r, rz(angles[2]) @ ry(angles[1]) @ rx(angles[0]), atol=1e-5)
            assert np.allclose(net.output("B.OUTPUT"), a, atol=1e-3)
    finally:
        net.close()


def test_gimbal_lock_gives_an_equivalent_rotation(tmp_path):
    out, _ = convert(tmp_path, "30 90 10", input_format="axayaz", output_format="axayaz",
                     angle_unit="degrees")
    got = rz(np.radians(out[2])) @ ry(np.radians(out[1])) @ rx(np.radians(out[0]))
    want = rz(np.radians(10)) @ ry(np.radians(90)) @ rx(np.radians(30))
    assert np.allclose(got, want, atol=1e-5)


def test_zero_quaternion_is_no_rotation_with_one_warning(tmp_path):
    out, warnings = convert(tmp_path, "0 0 0 0", ticks=3, input_format="quaternion",
                            output_format="matrix")
    assert np.array_equal(out, np.eye(4).reshape(-1))
    assert len(warnings) == 1


def test_wrong_input_size_is_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="needs 6 values"):
        convert(tmp_path, "1 2 3", input_format="xyzaxayaz")
    with pytest.raises(ikaros.ModelError, match="needs 3 values"):
        _convert_v3(tmp_path, "1, 2, 3, 4")         # Ikaros 2 only reads longer inputs


def test_ikaros_2_reads_the_first_values_of_a_longer_input(tmp_path):
    # golden-v2 RotationConverter "vector": four values in xyz form give the first three
    out, warnings = convert(tmp_path, "0.5 -1 2 0.25")
    assert np.array_equal(out, [0.5, -1, 2]) and len(warnings) == 1
    out, _ = convert(tmp_path, "1 2 3 30 0 0 9", input_format="xyzaxayaz",
                     output_format="matrix")
    assert np.allclose(out.reshape(4, 4), pose(1, 2, 3, np.radians(30), 0, 0), atol=1e-6)


def _convert_v3(tmp_path, data, **attrs):
    text = " ".join(f'{k}="{v}"' for k, v in attrs.items())
    net = load(tmp_path, f'<module class="Constant" name="C" data="{data}"/>'
                         f'<module class="RotationConverter" name="R" {text}/>'
                         '<connection source="C.OUTPUT" target="R.INPUT" delay="0"/>',
               dialect="3")
    try:
        net.step()
        return net.output("R.OUTPUT").copy()
    finally:
        net.close()


def test_ikaros_3_shapes_a_matrix_is_4x4_and_a_pose_a_row(tmp_path):
    # golden/README.md: a matrix output has shape [4, 4]; a pose is one row
    out = _convert_v3(tmp_path, "0.25 0 0.125", input_format="axayaz",
                      output_format="matrix", angle_unit="turns")
    expected = np.eye(4)
    expected[:3, :3] = rz(np.pi / 4) @ rx(np.pi / 2)
    assert out.shape == (4, 4) and np.allclose(out, expected, atol=1e-6)
    out = _convert_v3(tmp_path, "0 -1 0 1; 1 0 0 2; 0 0 1 3; 0 0 0 1",
                      input_format="matrix", output_format="xyzaxayaz")
    assert out.shape == (1, 6) and np.allclose(out, [[1, 2, 3, 0, 0, 90]], atol=1e-5)


def test_ikaros_3_quaternions_are_zero_unless_computed(tmp_path):
    out = _convert_v3(tmp_path, "0 0 90", input_format="axayaz", output_format="quaternion")
    assert out.shape == (1, 4) and not out.any()
    out = _convert_v3(tmp_path, "0 0 90", input_format="axayaz", output_format="quaternion",
                      quaternions="computed")
    assert np.allclose(out, [[0, 0, np.sqrt(0.5), np.sqrt(0.5)]], atol=1e-6)


def test_size_x_and_size_y_give_the_block_of_the_matrix_form(tmp_path):
    m = pose(1, -2, 0.5, 0.3, 0.2, -0.4)
    angles = "1 -2 0.5 0.3 0.2 -0.4"
    out = _convert_v3(tmp_path, angles, input_format="xyzaxayaz", output_format="matrix",
                      angle_unit="radians", size_y=3)
    assert out.shape == (3, 4) and np.allclose(out, m[:3, :], atol=1e-6)
    out = _convert_v3(tmp_path, angles, input_format="xyzaxayaz", output_format="matrix",
                      angle_unit="radians", size_x=3, size_y=3)
    assert out.shape == (3, 3) and np.allclose(out, m[:3, :3], atol=1e-6)
    out, _ = convert(tmp_path, angles, input_format="xyzaxayaz", output_format="matrix",
                     angle_unit="radians", size_y=3)              # Ikaros 2 file: 1-D
    assert out.shape == (12,) and np.allclose(out, m[:3, :].reshape(-1), atol=1e-6)
    rows = "; ".join(" ".join(repr(float(v)) for v in row) for row in m[:3, :])
    out = _convert_v3(tmp_path, rows, input_format="matrix", output_format="xyzaxayaz",
                      angle_unit="radians", size_y=3)
    assert np.allclose(out, [[1, -2, 0.5, 0.3, 0.2, -0.4]], atol=1e-5)


def test_size_x_and_size_y_must_be_3_or_4(tmp_path):
    with pytest.raises(ikaros.ModelError, match="size_x"):
        _convert_v3(tmp_path, "1, 2, 3", output_format="matrix", size_x=5)
