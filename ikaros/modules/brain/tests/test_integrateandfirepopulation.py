"""Tests of the IntegrateAndFirePopulation module (Ikaros 3, MODULES-V3 §11)."""
import math

import numpy as np
import pytest

from ikaros.testing import load_body as load


def _net(tmp_path, current, attrs="", tick_duration="0.001"):
    return load(tmp_path, f'<module class="Constant" name="I" data="{current}"/>'
                          f'<module class="IntegrateAndFirePopulation" name="N" {attrs}/>'
                          '<connection source="I.OUTPUT" target="N.INPUT" delay="0"/>',
                tick_duration=tick_duration)


def test_lif_reference_value_after_twenty_ticks(tmp_path):
    # MODULES-V3 §11 [oracle]: LIF, I = 0.2, tick 1 ms: after 20 ticks V = -52.357594
    net = _net(tmp_path, "0.2")
    try:
        for _ in range(20):
            net.step()
        assert net.output("N.VOLTAGE")[0] == pytest.approx(-52.357594, abs=2e-5)
        assert net.output("N.SPIKE_COUNT")[0] == 0
    finally:
        net.close()


def test_lif_spikes_then_stays_at_reset_for_the_refractory_period(tmp_path):
    # V∞ = -65 + 100*0.5 = -15: V = -15 + (-65 + 15) e^(-t/τ) reaches -50 at t = τ ln(50/35)
    net = _net(tmp_path, "0.5", 'refractory_period="0.003"')
    t_spike = 0.02 * math.log(50 / 35)
    try:
        times = []
        for k in range(1, 25):
            net.step()
            if net.output("N.SPIKES")[0]:
                times.append(k)
                assert net.output("N.FIRING_RATE")[0] == 1000
                assert net.output("N.VOLTAGE")[0] == -65
        assert times[0] == math.ceil(t_spike / 0.001)
        # after the spike: 3 ms at reset, then the climb from -65 again takes t_spike
        assert times[1] - times[0] == pytest.approx(3 + t_spike / 0.001, abs=1.5)
    finally:
        net.close()


def test_reset_restarts_the_neurons(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="I" data="0.3"/>'
                         '<module class="Constant" name="R" data="1"/>'
                         '<module class="IntegrateAndFirePopulation" name="N" '
                         'initial_potential="-70"/>'
                         '<connection source="I.OUTPUT" target="N.INPUT" delay="0"/>'
                         '<connection source="R.OUTPUT" target="N.RESET" delay="0"/>',
               tick_duration="0.001")
    try:
        for _ in range(3):
            net.step()
            v_inf = -65 + 30.0
            expected = v_inf + (-70 - v_inf) * np.exp(-0.001 / 0.02)
            assert net.output("N.VOLTAGE")[0] == pytest.approx(expected, abs=1e-4)
    finally:
        net.close()
