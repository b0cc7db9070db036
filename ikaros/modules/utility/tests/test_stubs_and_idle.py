"""Tests of Ikaros 3's Idle, and of the classes Ikaros 3 ships as stubs (Protocol,
Cerebellum: MODULES-V3 §14, §19), which run and output zeros as there."""
import time

import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load


def test_idle_sleeps_at_init_and_on_every_tick(tmp_path):
    start = time.monotonic()
    net = load(tmp_path, '<module class="Idle" name="I" init="0.2" duration="0.1"/>')
    try:
        assert time.monotonic() - start >= 0.2
        start = time.monotonic()
        net.run(ticks=3)
        assert time.monotonic() - start >= 0.3
    finally:
        net.close()


@pytest.mark.parametrize("attrs, missing", [('duration="0"', "init"), ('init="0"', "duration")])
def test_idle_needs_both_parameters(tmp_path, attrs, missing):
    with pytest.raises(ikaros.ModelError, match=f'parameter "{missing}" has no default'):
        load(tmp_path, f'<module class="Idle" name="I" {attrs}/>')


def test_protocol_and_cerebellum_output_zeros(tmp_path):
    net = load(tmp_path, '<module class="Protocol" name="P" trials="3"/>'
                         '<module class="Constant" name="C" data="1 2"/>'
                         '<module class="Cerebellum" name="B"/>'
                         '<connection source="C.OUTPUT" target="B.INPUT" delay="0"/>'
                         '<connection source="C.OUTPUT" target="B.STATE" delay="0"/>'
                         '<connection source="C.OUTPUT" target="B.TARGET" delay="0"/>')
    try:
        net.run(ticks=3)
        assert np.array_equal(net.output("P.STIMULUS"), [0, 0, 0, 0])
        assert net.output("P.REWARD").tolist() == [0] and net.output("B.OUTPUT").tolist() == [0]
        assert net.output("C.OUTPUT").tolist() == [1, 2]
    finally:
        net.close()
