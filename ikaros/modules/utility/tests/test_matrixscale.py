"""Tests of the MatrixScale module: about the middle (centre="middle") and about (cols / 2,
rows / 2) as Ikaros 2 scales (golden-v2 MatrixScale)."""
import math

import numpy as np

from ikaros.testing import load_body as load
from ikaros.testing import matrix_text

M = np.arange(1, 17, dtype=np.float32).reshape(4, 4)


def reference(m, fx, fy, centre="middle"):
    """Each output element takes the input element nearest to centre + offset / factor."""
    rows, cols = m.shape
    cx, cy = ((cols - 1) / 2, (rows - 1) / 2) if centre == "middle" else (cols / 2, rows / 2)
    out = np.zeros_like(m)

    def near(v):
        return int(math.floor(v + 0.5)) if v >= 0 else int(math.ceil(v - 0.5))

    for i in range(rows):
        for j in range(cols):
            x, y = near(cx + (j - cx) / fx), near(cy + (i - cy) / fy)
            if 0 <= x < cols and 0 <= y < rows:
                out[i, j] = m[y, x]
    return out


def scaled(tmp_path, m, fx, fy, ticks=2, centre="middle"):
    net = load(tmp_path, f'<module class="Constant" name="C" data="{matrix_text(m)}"/>'
               f'<module class="Constant" name="X" data="{fx!r}"/>'
               f'<module class="Constant" name="Y" data="{fy!r}"/>'
               f'<module class="MatrixScale" name="S" centre="{centre}"/>'
               '<connection source="C.OUTPUT" target="S.INPUT" delay="0"/>'
               '<connection source="X.OUTPUT" target="S.X" delay="0"/>'
               '<connection source="Y.OUTPUT" target="S.Y" delay="0"/>')
    try:
        for _ in range(ticks):
            net.step()
        return net.output("S.OUTPUT").copy(), net
    finally:
        net.close()


def test_identity_and_mirror(tmp_path):
    assert np.array_equal(scaled(tmp_path, M, 1, 1)[0], M)
    assert np.array_equal(scaled(tmp_path, M, -1, 1)[0], M[:, ::-1])
    assert np.array_equal(scaled(tmp_path, M, 1, -1)[0], M[::-1, :])


def test_zoom_in_hand_worked(tmp_path):
    got = scaled(tmp_path, M, 2, 2)[0]
    # centre 1.5: columns 0, 1, 2, 3 read 0.75, 1.25, 1.75, 2.25 -> 1, 1, 2, 2
    assert np.array_equal(got, [[6, 6, 7, 7], [6, 6, 7, 7], [10, 10, 11, 11],
                                [10, 10, 11, 11]])


def test_zoom_out_and_mixed_factors(tmp_path):
    for fx, fy in ((0.5, 0.5), (3, 0.7), (1.5, -2)):
        assert np.array_equal(scaled(tmp_path, M, fx, fy)[0], reference(M, fx, fy)), (fx, fy)
    # hand-worked: half size, the columns read -1.5, 0.5, 2.5, 4.5 -> -2, 1, 3, 5
    assert np.array_equal(scaled(tmp_path, M, 0.5, 1)[0][:, 1:3], M[:, [1, 3]])
    assert np.all(scaled(tmp_path, M, 0.5, 1)[0][:, [0, 3]] == 0)


def test_zero_factor_gives_zero_and_warns_once(tmp_path):
    got, net = scaled(tmp_path, M, 0, 1, ticks=3)
    assert np.array_equal(got, np.zeros((4, 4)))
    assert sum("cannot scale" in entry[3] for entry in net.log) == 1


def test_ikaros_2_scales_about_cols_and_rows_over_2(tmp_path):
    eye = np.eye(3, dtype=np.float32)
    got, _ = scaled(tmp_path, eye, 2.0, 0.5, centre="half")
    assert np.array_equal(got, reference(eye, 2.0, 0.5, "half"))
    assert np.array_equal(got, [[0, 0, 0], [1, 1, 0], [0, 0, 0]])      # golden-v2 "defaults"
    for fx, fy in ((0.7, 0.6), (1.5, -1.2), (-0.8, 3.0)):
        got, _ = scaled(tmp_path, M, fx, fy, centre="half")
        assert np.array_equal(got, reference(M, fx, fy, "half"))
