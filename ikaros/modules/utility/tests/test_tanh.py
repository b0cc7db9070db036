"""Tests of the Tanh module."""
import numpy as np

from ikaros.testing import load_body as load


def test_tanh_of_each_element_over_ticks(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R" outputsize_x="3" outputsize_y="2" '
                         'min="-4" max="4" seed="3"/>\n'
                         '<module class="Tanh" name="T"/>\n'
                         '<connection source="R.OUTPUT" target="T.INPUT" delay="0"/>')
    try:
        for _ in range(4):
            net.step()
            x = net.output("R.OUTPUT").astype(np.float64)
            y = net.output("T.OUTPUT")
            assert y.shape == (2, 3) and y.dtype == np.float32
            assert np.allclose(y, np.tanh(x), atol=1e-6)
    finally:
        net.close()


def test_hand_worked_values_and_debug_print(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="0 1 -1 100"/>\n'
                         '<module class="Tanh" name="T" debug="yes"/>\n'
                         '<connection source="C.OUTPUT" target="T.INPUT" delay="0"/>')
    try:
        net.step()
        assert np.allclose(net.output("T.OUTPUT"), [0, 0.7615942, -0.7615942, 1])
        assert any(where == "T" for (_, _, where, _) in net.log)
    finally:
        net.close()
