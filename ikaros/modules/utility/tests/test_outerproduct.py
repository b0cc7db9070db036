"""Tests of the OuterProduct module (Ikaros 2: accumulated over the ticks with rows and
columns swapped, golden-v2 OuterProduct; result="outer": this tick's product)."""

import numpy as np
import pytest

from ikaros.testing import load_body as load


def test_hand_worked_shape_follows_the_formula(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="A" data="1 2"/>'
                         '<module class="Constant" name="B" data="3 4 5"/>'
                         '<module class="OuterProduct" name="O" result="outer"/>'
                         '<connection source="A.OUTPUT" target="O.INPUT1" delay="0"/>'
                         '<connection source="B.OUTPUT" target="O.INPUT2" delay="0"/>')
    try:
        net.step()
        out = net.output("O.OUTPUT")
        assert out.shape == (2, 3) and out.dtype == np.float32
        assert np.array_equal(out, [[3, 4, 5], [6, 8, 10]])     # out[j][i] = a[j] * b[i]
    finally:
        net.close()


def test_matrix_inputs_are_flattened_and_ticks_follow_the_input(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="A" outputsize_x="2" outputsize_y="2" '
                         'min="-1" seed="1"/>'
                         '<module class="Randomizer" name="B" outputsize="3" seed="2"/>'
                         '<module class="OuterProduct" name="O" result="outer"/>'
                         '<connection source="A.OUTPUT" target="O.INPUT1" delay="0"/>'
                         '<connection source="B.OUTPUT" target="O.INPUT2" delay="0"/>')
    try:
        assert net.output("O.OUTPUT").shape == (4, 3)
        for _ in range(3):
            net.step()
            a = net.output("A.OUTPUT").reshape(-1)
            b = net.output("B.OUTPUT")
            expected = [[a[j] * b[i] for i in range(3)] for j in range(4)]
            assert np.allclose(net.output("O.OUTPUT"), expected)
    finally:
        net.close()


def _accumulated(a, b, ticks):
    """Ikaros 2's output after ``ticks`` ticks of constant a and b: n2 x n1, filled row by
    row with out[j][i] += a[j] * b[i] for j < min(n1, n2), i < n2 (flat index j * n1 + i)."""
    n1, n2 = len(a), len(b)
    flat = np.zeros(n1 * n2)
    for _ in range(ticks):
        for j in range(min(n1, n2)):
            for i in range(n2):
                if j * n1 + i < flat.size:
                    flat[j * n1 + i] += np.float32(a[j]) * np.float32(b[i])
    return flat.reshape(n2, n1)


@pytest.mark.parametrize("a, b", [([0.5, -1, 2, 0.25], [0.9, -1.5, 3.3, 0.5]),
                                  ([0.5, -1, 2, 0.25], [1, 2, -1]),
                                  ([1, 2], [3, 4, 5, 6])])
def test_ikaros_2_accumulates_with_rows_and_columns_swapped(tmp_path, a, b):
    text = " ".join
    net = load(tmp_path, f'<module class="Constant" name="A" data="{text(map(str, a))}"/>'
                         f'<module class="Constant" name="B" data="{text(map(str, b))}"/>'
                         '<module class="OuterProduct" name="O"/>'
                         '<connection source="A.OUTPUT" target="O.INPUT1" delay="0"/>'
                         '<connection source="B.OUTPUT" target="O.INPUT2" delay="0"/>')
    with net:
        for ticks in (1, 2, 3):
            net.step()
            assert np.allclose(net.output("O.OUTPUT"), _accumulated(a, b, ticks), rtol=1e-6)
        assert any("Ikaros 2" in entry[3] for entry in net.log) == (len(a) != len(b))
