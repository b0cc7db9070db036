"""Tests of the Subtract module."""

import numpy as np

from ikaros.testing import load_body as load



def test_subtracts(tmp_path):
    net = load(tmp_path,
               '<module class="Constant" name="A" data="1 2; 3 4"/>\n'
               '<module class="Constant" name="B" data="0.5 4; -1 4"/>\n'
               '<module class="Subtract" name="D"/>\n'
               '<connection source="A.OUTPUT" target="D.INPUT1" delay="0"/>\n'
               '<connection source="B.OUTPUT" target="D.INPUT2" delay="0"/>')
    try:
        net.run(ticks=2)
        out = net.output("D.OUTPUT")
        assert out.dtype == np.float32
        assert np.array_equal(out, [[0.5, -2], [4, 0]])
    finally:
        net.close()


def test_unconnected_input2_copies_input1(tmp_path):
    net = load(tmp_path,
               '<module class="Sweep" name="W" min="0" max="3" step="1" outputsize="2"/>\n'
               '<module class="Subtract" name="D"/>\n'
               '<connection source="W.OUTPUT" target="D.INPUT1" delay="0"/>')
    try:
        got = []
        for _ in range(5):
            net.step()
            got.append(net.output("D.OUTPUT").tolist())
        assert got == [[1, 1], [2, 2], [3, 3], [0, 0], [1, 1]]
    finally:
        net.close()


def test_changing_inputs(tmp_path):
    net = load(tmp_path,
               '<module class="Sweep" name="W" min="0" max="10" step="2"/>\n'
               '<module class="Sweep" name="V" min="0" max="10" step="1"/>\n'
               '<module class="Subtract" name="D"/>\n'
               '<connection source="W.OUTPUT" target="D.INPUT1" delay="0"/>\n'
               '<connection source="V.OUTPUT" target="D.INPUT2" delay="0"/>')
    try:
        for tick in range(4):
            net.step()
            assert net.output("D.OUTPUT")[0] == 2 * (tick + 1) - (tick + 1)
    finally:
        net.close()
