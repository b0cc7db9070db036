"""Tests of the Abs module."""
import numpy as np

from ikaros.testing import load_body as load


def test_absolute_value_keeps_the_shape(tmp_path):
    net = load(tmp_path,
               '<module class="Constant" name="C" data="1 -2.5; -0 3"/>\n'
               '<module class="Abs" name="A"/>\n'
               '<connection source="C.OUTPUT" target="A.INPUT" delay="0"/>')
    try:
        net.step()
        out = net.output("A.OUTPUT")
        assert out.shape == (2, 2) and out.dtype == np.float32
        assert np.array_equal(out, [[1, 2.5], [0, 3]])
    finally:
        net.close()


def test_follows_a_changing_input(tmp_path):
    # Sweep from -2 by 1: writes -2 in init and -2 + (k+1) on tick k (wrapping past 2).
    net = load(tmp_path,
               '<module class="Sweep" name="S" min="-2" max="2" step="1" outputsize="3"/>\n'
               '<module class="Abs" name="A"/>\n'
               '<connection source="S.OUTPUT" target="A.INPUT" delay="0"/>')
    try:
        for _ in range(8):
            net.step()
            s = net.output("S.OUTPUT")
            assert np.array_equal(net.output("A.OUTPUT"), np.abs(s))
    finally:
        net.close()
