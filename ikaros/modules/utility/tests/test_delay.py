"""Tests of the Delay module."""
import numpy as np
import pytest

from ikaros.testing import load_body as load

# Sweep from 0 by 1: 0 in init and k + 1 on tick k.
SWEEP = '<module class="Sweep" name="S" min="0" max="1000" step="1" outputsize="2"/>\n'


@pytest.mark.parametrize("delay", [0, 1, 2, 3, 5])
def test_delay_counts_the_default_connection(tmp_path, delay):
    net = load(tmp_path, SWEEP +
               f'<module class="Delay" name="D" delay="{delay}"/>\n'
               '<connection source="S.OUTPUT" target="D.INPUT"/>')
    try:
        for tick in range(8):
            net.step()
            # The default connection brings S of tick-1 (its init value 0 on tick 0);
            # the module adds delay-1 ticks, and outputs 0 until its line has filled.
            total = max(1, delay)
            expected = tick + 1 - total if tick >= total - 1 else 0
            assert np.array_equal(net.output("D.OUTPUT"), [expected, expected]), tick
    finally:
        net.close()


def test_matrix_input_keeps_its_shape(tmp_path):
    net = load(tmp_path,
               '<module class="Constant" name="C" data="1 2; 3 4"/>\n'
               '<module class="Delay" name="D" delay="3"/>\n'
               '<connection source="C.OUTPUT" target="D.INPUT" delay="0"/>')
    try:
        net.step()
        assert net.output("D.OUTPUT").shape == (2, 2) and not net.output("D.OUTPUT").any()
        net.step()
        assert not net.output("D.OUTPUT").any()
        net.step()
        assert np.array_equal(net.output("D.OUTPUT"), [[1, 2], [3, 4]])
    finally:
        net.close()
