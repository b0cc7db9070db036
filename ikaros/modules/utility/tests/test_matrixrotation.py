"""Tests of the MatrixRotation module: about the middle of the matrix (centre="middle"), and about
(cols / 2, rows / 2) as Ikaros 2 turns (golden-v2 MatrixRotation)."""
import math

import numpy as np

from ikaros.testing import load_body as load
from ikaros.testing import matrix_text

SQUARE = np.arange(16, dtype=np.float32).reshape(4, 4)


def rotated(tmp_path, m, angle, fmt="deg", centre="middle"):
    net = load(tmp_path, f'<module class="Constant" name="C" data="{matrix_text(m)}"/>'
               f'<module class="Constant" name="A" data="{angle!r}"/>'
               f'<module class="MatrixRotation" name="R" angle_format="{fmt}" '
               f'centre="{centre}"/>'
               '<connection source="C.OUTPUT" target="R.INPUT" delay="0"/>'
               '<connection source="A.OUTPUT" target="R.ANGLE" delay="0"/>')
    try:
        net.step()
        first = net.output("R.OUTPUT").copy()
        net.step()
        assert np.array_equal(net.output("R.OUTPUT"), first)
        return first
    finally:
        net.close()


def test_quarter_and_half_turns_are_exact(tmp_path):
    assert np.array_equal(rotated(tmp_path, SQUARE, 0), SQUARE)
    assert np.array_equal(rotated(tmp_path, SQUARE, 90), np.rot90(SQUARE, 1))
    assert np.array_equal(rotated(tmp_path, SQUARE, -90), np.rot90(SQUARE, -1))
    assert np.array_equal(rotated(tmp_path, SQUARE, 180), np.rot90(SQUARE, 2))
    assert np.array_equal(rotated(tmp_path, SQUARE, math.pi / 2, "rad"), np.rot90(SQUARE, 1))
    odd = np.arange(9, dtype=np.float32).reshape(3, 3)
    assert np.array_equal(rotated(tmp_path, odd, 270), np.rot90(odd, -1))


def test_45_degrees_nearest_neighbour(tmp_path):
    m = np.arange(1, 10, dtype=np.float32).reshape(3, 3)
    got = rotated(tmp_path, m, 45)
    # independent: for each output (i, j), the source c + R(45)(p - c), rounded
    c = 1.0
    s = math.sqrt(0.5)
    expected = np.zeros((3, 3))
    for i in range(3):
        for j in range(3):
            x = c + s * (j - c) - s * (i - c)
            y = c + s * (j - c) + s * (i - c)
            xi, yi = int(math.floor(x + 0.5)), int(math.floor(y + 0.5))
            if 0 <= xi < 3 and 0 <= yi < 3:
                expected[i, j] = m[yi, xi]
    assert np.array_equal(got, expected)
    # hand-worked: the centre stays and the ring of eight moves one step counterclockwise
    assert np.array_equal(got, [[2, 3, 6], [1, 5, 9], [4, 7, 8]])


def test_non_square_corners_fall_outside(tmp_path):
    m = np.arange(1, 7, dtype=np.float32).reshape(2, 3)
    got = rotated(tmp_path, m, 90)
    # centre (1, 0.5): output (i, j) reads x = 1 - (i - 0.5), y = 0.5 + (j - 1), rounded
    # half away from zero: x is 2 (i = 0) or 1 (i = 1); y is -1, 1, 2 for j = 0, 1, 2, and
    # only y = 1 is inside
    assert np.array_equal(got, [[0, 6, 0], [0, 5, 0]])


def test_colour_image_turns_every_channel(tmp_path):
    stack = np.arange(18, dtype=np.float32).reshape(2, 3, 3)
    nested = "[" + ",".join("[" + ",".join("[" + ",".join(str(float(v)) for v in row) + "]"
                                           for row in ch) + "]" for ch in stack) + "]"
    net = load(tmp_path, f'<module class="Constant" name="C" data="{nested}"/>'
               '<module class="Sweep" name="A" min="0" max="360" step="90"/>'
               '<module class="MatrixRotation" name="R" centre="middle"/>'
               '<connection source="C.OUTPUT" target="R.INPUT" delay="0"/>'
               '<connection source="A.OUTPUT" target="R.ANGLE" delay="0"/>')
    try:
        for tick in range(5):             # A: 90, 180, 270, 360, 0
            net.step()
            turns = ((tick + 1) % 5) % 4
            assert net.output("R.OUTPUT").shape == (2, 3, 3)
            assert np.array_equal(net.output("R.OUTPUT"), np.rot90(stack, turns, axes=(1, 2)))
    finally:
        net.close()


def _turned_about_half(m, angle):
    """Each output (i, j) reads the source (cx, cy) + R(angle) (j - cx, i - cy), rounded to
    the nearest element, with Ikaros 2's centre (cols / 2, rows / 2)."""
    rows, cols = m.shape
    cx, cy = cols / 2, rows / 2
    c, s = math.cos(angle), math.sin(angle)
    out = np.zeros_like(m)
    for i in range(rows):
        for j in range(cols):
            x = math.floor(cx + c * (j - cx) - s * (i - cy) + 0.5)
            y = math.floor(cy + s * (j - cx) + c * (i - cy) + 0.5)
            if 0 <= x < cols and 0 <= y < rows:
                out[i, j] = m[y, x]
    return out


def test_ikaros_2_turns_about_cols_and_rows_over_2(tmp_path):
    eye = np.eye(3, dtype=np.float32)
    got = rotated(tmp_path, eye, 30, centre="half")
    assert np.array_equal(got, _turned_about_half(eye, math.radians(30)))
    assert np.array_equal(got, [[0, 0, 0], [1, 1, 0], [0, 0, 1]])      # golden-v2 "deg"
    for angle in (0.5, 2.0, -1.2):
        assert np.array_equal(rotated(tmp_path, SQUARE, angle, "rad", centre="half"),
                              _turned_about_half(SQUARE, angle))
    # a half turn of an even size is shifted by one element
    assert np.array_equal(rotated(tmp_path, SQUARE, 180, centre="half"),
                          _turned_about_half(SQUARE, math.pi))
