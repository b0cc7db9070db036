"""Tests of M02_Cortex."""
import numpy as np

from ikaros.testing import load_body as load


def test_copies_the_input(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1 2; 3 4"/>'
               '<module class="M02_Cortex" name="X"/>'
               '<connection source="C.OUTPUT" target="X.INPUT" delay="0"/>')
    try:
        net.step()
        assert np.array_equal(net.output("X.OUTPUT"), [[1, 2], [3, 4]])
    finally:
        net.close()


def test_outputsize_truncates_or_pads(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="1 2 3"/>'
               '<module class="M02_Cortex" name="Short" outputsize="2"/>'
               '<module class="M02_Cortex" name="Long" outputsize="5"/>'
               '<connection source="C.OUTPUT" target="Short.INPUT" delay="0"/>'
               '<connection source="C.OUTPUT" target="Long.INPUT" delay="0"/>')
    try:
        net.step()
        assert np.array_equal(net.output("Short.OUTPUT"), [1, 2])
        assert np.array_equal(net.output("Long.OUTPUT"), [1, 2, 3, 0, 0])
    finally:
        net.close()
