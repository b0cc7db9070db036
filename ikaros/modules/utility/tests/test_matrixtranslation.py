"""Tests of the MatrixTranslation module."""
import numpy as np

from ikaros.testing import load_body as load
from ikaros.testing import matrix_text

M = np.arange(1, 13, dtype=np.float32).reshape(3, 4)


def reference(m, dx, dy):
    """OUTPUT[i, j] = INPUT[i - dy, j - dx], 0 outside."""
    out = np.zeros_like(m)
    rows, cols = m.shape[-2:]
    for i in range(rows):
        for j in range(cols):
            if 0 <= i - dy < rows and 0 <= j - dx < cols:
                out[..., i, j] = m[..., i - dy, j - dx]
    return out


def shifted(tmp_path, x, y, m=M):
    net = load(tmp_path, f'<module class="Constant" name="C" data="{matrix_text(m)}"/>'
               f'<module class="Constant" name="X" data="{x!r}"/>'
               f'<module class="Constant" name="Y" data="{y!r}"/>'
               '<module class="MatrixTranslation" name="T"/>'
               '<connection source="C.OUTPUT" target="T.INPUT" delay="0"/>'
               '<connection source="X.OUTPUT" target="T.X" delay="0"/>'
               '<connection source="Y.OUTPUT" target="T.Y" delay="0"/>')
    try:
        net.run(ticks=2)
        return net.output("T.OUTPUT").copy()
    finally:
        net.close()


def test_hand_worked_shift(tmp_path):
    assert np.array_equal(shifted(tmp_path, 1, 1), [[0, 0, 0, 0], [0, 1, 2, 3], [0, 5, 6, 7]])
    assert np.array_equal(shifted(tmp_path, -2, 0), [[3, 4, 0, 0], [7, 8, 0, 0],
                                                     [11, 12, 0, 0]])


def test_shifts_against_reference_with_rounding(tmp_path):
    for x, y in ((0, 0), (2, -1), (-3, 2), (0.4, 0.5), (-0.5, -1.6)):
        rx = int(np.floor(abs(x) + 0.5)) * int(np.sign(x))
        ry = int(np.floor(abs(y) + 0.5)) * int(np.sign(y))
        assert np.array_equal(shifted(tmp_path, x, y), reference(M, rx, ry)), (x, y)


def test_shift_past_the_edge_gives_zeros(tmp_path):
    assert np.array_equal(shifted(tmp_path, 4, 0), np.zeros((3, 4)))
    assert np.array_equal(shifted(tmp_path, 0, -3), np.zeros((3, 4)))


def test_one_dimensional_input_and_changing_shift(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1 2 3 4 5"/>'
               '<module class="Sweep" name="X" min="-2" max="2" step="1"/>'
               '<module class="Constant" name="Y" data="0"/>'
               '<module class="MatrixTranslation" name="T"/>'
               '<connection source="C.OUTPUT" target="T.INPUT" delay="0"/>'
               '<connection source="X.OUTPUT" target="T.X" delay="0"/>'
               '<connection source="Y.OUTPUT" target="T.Y" delay="0"/>')
    try:
        row = np.array([[1, 2, 3, 4, 5]], dtype=np.float32)
        for tick in range(5):                  # X: -1, 0, 1, 2, -2
            net.step()
            dx = [-1, 0, 1, 2, -2][tick]
            assert np.array_equal(net.output("T.OUTPUT"), reference(row, dx, 0)[0])
    finally:
        net.close()
