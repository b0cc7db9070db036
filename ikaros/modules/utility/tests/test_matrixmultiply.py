"""Tests of the MatrixMultiply module."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load, matrix_text


def two(tmp_path, a, b, attrs=""):
    return load(tmp_path, f'<module class="Constant" name="A" data="{a}"/>'
                f'<module class="Constant" name="B" data="{b}"/>'
                f'<module class="MatrixMultiply" name="M" {attrs}/>'
                '<connection source="A.OUTPUT" target="M.INPUT1" delay="0"/>'
                '<connection source="B.OUTPUT" target="M.INPUT2" delay="0"/>')


def test_hand_worked_product(tmp_path):
    net = two(tmp_path, "1 2 3; 4 5 6", "1 0; 0 1; 2 -1")
    try:
        assert net.output("M.OUTPUT").shape == (2, 2)
        net.step()
        assert np.array_equal(net.output("M.OUTPUT"), [[7, -1], [16, -1]])
    finally:
        net.close()


def test_trans_2(tmp_path):
    net = two(tmp_path, "1 2 3; 4 5 6", "1 0 2; 0 1 -1",
              'trans_2="yes" trans_2_result="transpose"')
    try:
        assert net.output("M.OUTPUT").shape == (2, 2)
        net.step()
        assert np.array_equal(net.output("M.OUTPUT"), [[7, -1], [16, -1]])
    finally:
        net.close()


@pytest.mark.parametrize("a, b", [
    ([[1, -2, 3], [0.5, 4, -1.5]], [[2, 0.5, -1], [1.5, -2, 0.25]]),    # golden-v2 trans_2
    ([[1, 2], [3, 4], [5, 6]], [[1, 0], [2, 1]]),                        # 3 x 2 output
])
def test_trans_2_as_ikaros_2_computes_it(tmp_path, a, b):
    a, b = np.array(a, np.float32), np.array(b, np.float32)
    (m, k), n = a.shape, b.shape[0]
    want = np.zeros(m * n)
    for i in range(m):                     # out.flat[i + j M] = sum A[i, k] B.flat[j + k N]
        for j in range(n):
            want[i + j * m] = sum(a[i, q] * b.reshape(-1)[j + q * n] for q in range(k))
    with two(tmp_path, matrix_text(a), matrix_text(b), 'trans_2="yes"') as net:
        net.step()
        assert net.output("M.OUTPUT").shape == (m, n)
        assert np.allclose(net.output("M.OUTPUT").reshape(-1), want)


def test_vectors(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="A" data="1 2 3; 4 5 6"/>'
               '<module class="Constant" name="V" data="1 1 2"/>'
               '<module class="Constant" name="W" data="1 -1"/>'
               '<module class="MatrixMultiply" name="MV"/>'
               '<module class="MatrixMultiply" name="WA"/>'
               '<module class="MatrixMultiply" name="VV"/>'
               '<connection source="A.OUTPUT" target="MV.INPUT1" delay="0"/>'
               '<connection source="V.OUTPUT" target="MV.INPUT2" delay="0"/>'
               '<connection source="W.OUTPUT" target="WA.INPUT1" delay="0"/>'
               '<connection source="A.OUTPUT" target="WA.INPUT2" delay="0"/>'
               '<connection source="V.OUTPUT" target="VV.INPUT1" delay="0"/>'
               '<connection source="V.OUTPUT" target="VV.INPUT2" delay="0"/>')
    try:
        net.step()
        assert np.array_equal(net.output("MV.OUTPUT"), [9, 21])
        assert np.array_equal(net.output("WA.OUTPUT"), [-3, -3, -3])
        assert np.array_equal(net.output("VV.OUTPUT"), [6])
    finally:
        net.close()


def test_random_inputs_over_ticks(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="A" outputsize_x="4" '
               'outputsize_y="3" seed="1"/>'
               '<module class="Randomizer" name="B" outputsize_x="5" outputsize_y="4" '
               'seed="2"/>'
               '<module class="MatrixMultiply" name="M"/>'
               '<connection source="A.OUTPUT" target="M.INPUT1" delay="0"/>'
               '<connection source="B.OUTPUT" target="M.INPUT2" delay="0"/>')
    try:
        for _ in range(3):
            net.step()
            a = net.output("A.OUTPUT").astype(np.float64)
            b = net.output("B.OUTPUT").astype(np.float64)
            expected = np.array([[sum(a[i, k] * b[k, j] for k in range(4)) for j in range(5)]
                                 for i in range(3)])
            assert np.allclose(net.output("M.OUTPUT"), expected, atol=1e-5)
    finally:
        net.close()


def test_mismatched_sizes_are_an_error(tmp_path):
    with pytest.raises(ikaros.ModelError, match="cannot multiply"):
        two(tmp_path, "1 2 3; 4 5 6", "1 2; 3 4")
