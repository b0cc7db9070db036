"""Tests of the Sum module."""

import numpy as np

from ikaros.testing import load_body as load



def test_sums_1d_and_2d(tmp_path):
    net = load(tmp_path,
               '<module class="Constant" name="A" data="1 2 3"/>\n'
               '<module class="Constant" name="B" data="1 2; 3 4.5"/>\n'
               '<module class="Sum" name="S"/>\n'
               '<module class="Sum" name="T"/>\n'
               '<connection source="A.OUTPUT" target="S.INPUT" delay="0"/>\n'
               '<connection source="B.OUTPUT" target="T.INPUT" delay="0"/>')
    try:
        net.step()
        s, t = net.output("S.OUTPUT"), net.output("T.OUTPUT")
        assert s.shape == (1,) and t.shape == (1,) and s.dtype == np.float32
        assert s[0] == 6 and t[0] == 10.5
    finally:
        net.close()


def test_sums_a_changing_input(tmp_path):
    net = load(tmp_path,
               '<module class="Sweep" name="W" min="-2" max="2" step="1" outputsize="3"/>\n'
               '<module class="Sum" name="S"/>\n'
               '<connection source="W.OUTPUT" target="S.INPUT"/>')
    try:
        got = []
        for _ in range(6):
            net.step()
            got.append(float(net.output("S.OUTPUT")[0]))
        # delay 1: W's values one tick late: -2 (init), -1, 0, 1, 2, -2
        assert got == [-6, -3, 0, 3, 6, -6]
    finally:
        net.close()
