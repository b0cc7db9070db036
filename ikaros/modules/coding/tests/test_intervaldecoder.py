"""Tests of the IntervalDecoder module."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load


def test_decodes_the_weighted_position(tmp_path):
    # Ikaros 2: min + step (sum_i i x_i - radius), not divided by the sum of x; with
    # normalize, the weighted mean of the centres
    net = load(tmp_path, '<module class="Randomizer" name="R" outputsize="8" seed="6"/>\n'
                         '<module class="IntervalDecoder" name="D" radius="1" min="-1" '
                         'max="2"/>\n'
                         '<module class="IntervalDecoder" name="N" radius="1" min="-1" '
                         'max="2" normalize="yes"/>\n'
                         '<connection source="R.OUTPUT" target="D.INPUT" delay="0"/>\n'
                         '<connection source="R.OUTPUT" target="N.INPUT" delay="0"/>')
    try:
        step = 3 / 5
        centres = -1 + (np.arange(8) - 1) * step
        for _ in range(4):
            net.step()
            x = net.output("R.OUTPUT").astype(np.float64)
            assert np.isclose(net.output("D.OUTPUT")[0], -1 + step * (np.arange(8) @ x - 1),
                              atol=1e-5)
            assert np.isclose(net.output("N.OUTPUT")[0], centres @ x / x.sum(), atol=1e-5)
    finally:
        net.close()


def test_round_trip_with_the_coder(tmp_path):
    # IntervalCoder quantises to its grid of centres (step 1/7); decoding gives that grid value
    # (step 0.04 never lands half-way between two centres, where two units tie)
    body = ('<module class="Sweep" name="S" min="0" max="1" step="0.04"/>\n'
            '<module class="IntervalCoder" name="C"/>\n'
            '<module class="IntervalDecoder" name="D"/>\n'
            '<connection source="S.OUTPUT" target="C.INPUT" delay="0"/>\n'
            '<connection source="C.OUTPUT" target="D.INPUT" delay="0"/>')
    net = load(tmp_path, body)
    try:
        for _ in range(26):
            net.step()
            x = float(net.output("S.OUTPUT")[0])
            assert np.isclose(net.output("D.OUTPUT")[0], np.round(x * 7) / 7, atol=1e-5)
    finally:
        net.close()


def test_hand_worked_and_unnormalised_code(tmp_path):
    # 5 units, radius 1: step 1/2, centres -1/2, 0, 1/2, 1, 3/2. The code scaled by 2 gives
    # Ikaros 2 0 + (2 + 4 + 6 - 1) / 2 = 5.5; normalized it decodes to 0.5
    body = ('<module class="Constant" name="K" data="0 2 2 2 0"/>\n'
            '<module class="IntervalDecoder" name="D"/>\n'
            '<module class="IntervalDecoder" name="N" normalize="yes"/>\n'
            '<connection source="K.OUTPUT" target="D.INPUT" delay="0"/>\n'
            '<connection source="K.OUTPUT" target="N.INPUT" delay="0"/>')
    net = load(tmp_path, body)
    try:
        net.step()
        assert np.isclose(net.output("D.OUTPUT")[0], 5.5)
        assert np.isclose(net.output("N.OUTPUT")[0], 0.5)
    finally:
        net.close()


def test_zero_input(tmp_path):
    # Ikaros 2: min - radius * step = -1; normalized: 0, with one warning
    net = load(tmp_path, '<module class="Constant" name="K" data="0 0 0 0"/>\n'
                         '<module class="IntervalDecoder" name="D"/>\n'
                         '<module class="IntervalDecoder" name="N" normalize="yes"/>\n'
                         '<connection source="K.OUTPUT" target="D.INPUT" delay="0"/>\n'
                         '<connection source="K.OUTPUT" target="N.INPUT" delay="0"/>')
    try:
        net.run(ticks=3)
        assert net.output("D.OUTPUT")[0] == -1
        assert net.output("N.OUTPUT")[0] == 0
        warnings = [m for (_, level, where, m) in net.log if where == "N" and level == 5]
        assert len(warnings) == 1
    finally:
        net.close()


def test_too_small_input_is_a_build_error(tmp_path):
    with pytest.raises(ikaros.ModelError):
        load(tmp_path, '<module class="Constant" name="K" data="0 1 0"/>\n'
                       '<module class="IntervalDecoder" name="D"/>\n'
                       '<connection source="K.OUTPUT" target="D.INPUT"/>')
