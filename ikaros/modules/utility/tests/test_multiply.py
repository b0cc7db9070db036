"""Tests of the Multiply module."""

import numpy as np

from ikaros.testing import load_body as load



def test_multiplies_1d_and_2d(tmp_path):
    net = load(tmp_path,
               '<module class="Constant" name="A" data="1 2 3"/>\n'
               '<module class="Constant" name="B" data="2 -0.5 0"/>\n'
               '<module class="Constant" name="C" data="1 2; 3 4"/>\n'
               '<module class="Constant" name="E" data="2 2; 0.5 -1"/>\n'
               '<module class="Multiply" name="M"/>\n'
               '<module class="Multiply" name="N"/>\n'
               '<connection source="A.OUTPUT" target="M.INPUT1" delay="0"/>\n'
               '<connection source="B.OUTPUT" target="M.INPUT2" delay="0"/>\n'
               '<connection source="C.OUTPUT" target="N.INPUT1" delay="0"/>\n'
               '<connection source="E.OUTPUT" target="N.INPUT2" delay="0"/>')
    try:
        net.run(ticks=2)
        assert net.output("M.OUTPUT").dtype == np.float32
        assert np.array_equal(net.output("M.OUTPUT"), [2, -1, 0])
        assert np.array_equal(net.output("N.OUTPUT"), [[2, 4], [1.5, -4]])
    finally:
        net.close()


def test_squares_a_ramp(tmp_path):
    net = load(tmp_path,
               '<module class="Sweep" name="W" min="0" max="3" step="1"/>\n'
               '<module class="Multiply" name="M"/>\n'
               '<connection source="W.OUTPUT" target="M.INPUT1" delay="0"/>\n'
               '<connection source="W.OUTPUT" target="M.INPUT2" delay="0"/>')
    try:
        got = []
        for _ in range(6):
            net.step()
            got.append(float(net.output("M.OUTPUT")[0]))
        assert got == [1, 4, 9, 0, 1, 4]
    finally:
        net.close()
