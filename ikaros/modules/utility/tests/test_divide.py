"""Tests of the Divide module."""
import numpy as np

from ikaros.module import WARNING
from ikaros.testing import load_body as load


def test_divides_element_wise(tmp_path):
    net = load(tmp_path,
               '<module class="Constant" name="A" data="1 2; 3 -4"/>\n'
               '<module class="Constant" name="B" data="2 8; -3 0.5"/>\n'
               '<module class="Divide" name="D"/>\n'
               '<connection source="A.OUTPUT" target="D.INPUT1" delay="0"/>\n'
               '<connection source="B.OUTPUT" target="D.INPUT2" delay="0"/>')
    try:
        net.step()
        assert np.array_equal(net.output("D.OUTPUT"), [[0.5, 0.25], [-1, -8]])
        assert not [e for e in net.log if e[1] == WARNING]
    finally:
        net.close()


def test_division_by_zero_gives_zero_and_one_warning(tmp_path):
    # The divisor sweeps 0, 1, 2, 0, 1, 2 ...: its init value 0 arrives on tick 0.
    net = load(tmp_path,
               '<module class="Constant" name="A" data="6 -6"/>\n'
               '<module class="Sweep" name="B" min="0" max="2" step="1" outputsize="2"/>\n'
               '<module class="Divide" name="D"/>\n'
               '<connection source="A.OUTPUT" target="D.INPUT1" delay="0"/>\n'
               '<connection source="B.OUTPUT" target="D.INPUT2"/>')
    try:
        for tick in range(7):
            net.step()
            b = tick % 3
            expected = [0, 0] if b == 0 else [6 / b, -6 / b]
            out = net.output("D.OUTPUT")
            assert np.all(np.isfinite(out))
            assert np.allclose(out, expected), tick
        warnings = [e for e in net.log if e[1] == WARNING and e[2].split(".")[-1] == "D"]
        assert len(warnings) == 1 and "division by zero" in warnings[0][3]
    finally:
        net.close()
