"""Tests of the OuterProduct module."""

import numpy as np

from ikaros.testing import load_body as load


def test_hand_worked_shape_follows_the_formula(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="A" data="1 2"/>'
                         '<module class="Constant" name="B" data="3 4 5"/>'
                         '<module class="OuterProduct" name="O"/>'
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
                         '<module class="OuterProduct" name="O"/>'
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
