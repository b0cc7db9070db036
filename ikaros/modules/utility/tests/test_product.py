"""Tests of the Product module."""

import numpy as np

from ikaros.testing import load_body as load


def test_hand_worked(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1 2; -3 4"/>'
                         '<module class="Product" name="P"/>'
                         '<connection source="C.OUTPUT" target="P.INPUT" delay="0"/>')
    try:
        net.step()
        out = net.output("P.OUTPUT")
        assert out.shape == (1,) and out.dtype == np.float32
        assert out[0] == -24
    finally:
        net.close()


def test_a_zero_gives_zero(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="5 0 7"/>'
                         '<module class="Product" name="P"/>'
                         '<connection source="C.OUTPUT" target="P.INPUT" delay="0"/>')
    try:
        net.step()
        assert net.output("P.OUTPUT")[0] == 0
    finally:
        net.close()


def test_follows_a_changing_input(tmp_path):
    net = load(tmp_path, '<module class="Randomizer" name="R" outputsize="4" min="0.5" max="2" '
                         'seed="3"/>'
                         '<module class="Product" name="P"/>'
                         '<connection source="R.OUTPUT" target="P.INPUT" delay="0"/>')
    try:
        for _ in range(5):
            net.step()
            r = net.output("R.OUTPUT").astype(np.float64)
            expected = r[0] * r[1] * r[2] * r[3]
            assert np.isclose(net.output("P.OUTPUT")[0], expected, rtol=1e-6)
    finally:
        net.close()
