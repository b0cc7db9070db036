"""Tests of the Sink module."""
import numpy as np

from ikaros.testing import load_body as load


def test_accepts_any_input_and_has_no_outputs(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1 2; 3 4"/>\n'
                         '<module class="Sink" name="S"/>\n'
                         '<connection source="C.OUTPUT" target="S.INPUT"/>')
    try:
        net.run(ticks=3)
        assert net.tick == 3
        assert np.array_equal(net.output("S.INPUT"), [[1, 2], [3, 4]])
        module = [i.module for i in net.schedule if i.path == "S"][0]
        assert module._ik_outputs == {}
    finally:
        net.close()
