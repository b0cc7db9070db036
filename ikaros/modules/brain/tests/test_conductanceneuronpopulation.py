"""Tests of the ConductanceNeuronPopulation module (Ikaros 3, MODULES-V3 §12)."""
import math

import numpy as np
import pytest

from ikaros.testing import load_body as load


def morris_lecar(I, ticks, tick=0.001, step=0.000025, V=-65.0):
    """Morris–Lecar with the default parameters, RK4 in float64 (MODULES-V3 §12)."""
    def f(V, w):
        m = 0.5 * (1 + math.tanh((V + 1.2) / 18))
        dV = 1000 * (I - 4.4 * m * (V - 120) - 8 * w * (V + 84) - 2 * (V + 60)) / 20
        dw = math.cosh((V - 2) / 60) * (0.5 * (1 + math.tanh((V - 2) / 30)) - w) / 0.025
        return dV, dw
    w = 0.5 * (1 + math.tanh((V - 2) / 30))
    out = []
    for _ in range(ticks):
        for _ in range(round(tick / step)):
            k1 = f(V, w)
            k2 = f(V + step / 2 * k1[0], w + step / 2 * k1[1])
            k3 = f(V + step / 2 * k2[0], w + step / 2 * k2[1])
            k4 = f(V + step * k3[0], w + step * k3[1])
            V += step / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
            w += step / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
            w = min(max(w, 0), 1)
        out.append((V, w))
    return out


def _net(tmp_path, model, current):
    return load(tmp_path, f'<module class="Constant" name="I" data="{current}"/>'
                          f'<module class="ConductanceNeuronPopulation" name="N" '
                          f'model="{model}" population_size="2"/>'
                          '<connection source="I.OUTPUT" target="N.CURRENT" delay="0"/>',
                tick_duration="0.001")


def test_morris_lecar_follows_the_equations(tmp_path):
    net = _net(tmp_path, "morris_lecar", "60 0")
    try:
        for V, w in morris_lecar(60, 8):
            net.step()
            assert net.output("N.VOLTAGE")[0] == pytest.approx(V, abs=2e-3)
            assert net.output("N.RECOVERY")[0] == pytest.approx(w, abs=1e-5)
    finally:
        net.close()


def test_hodgkin_huxley_rests_without_input_and_fires_with_it(tmp_path):
    net = _net(tmp_path, "hodgkin_huxley", "10 0")
    try:
        spikes = np.zeros(2)
        for _ in range(40):
            net.step()
            spikes += net.output("N.SPIKE_COUNT")
            assert abs(net.output("N.VOLTAGE")[1] + 65) < 0.1     # the resting neuron
        # 10 µA/cm² drives the squid axon at about 70 Hz: 2 or 3 spikes in 40 ms
        assert spikes[0] in (2, 3) and spikes[1] == 0
    finally:
        net.close()


@pytest.mark.parametrize("model", ["hodgkin_huxley", "morris_lecar"])
def test_the_compiled_loops_give_the_numpy_forms_values(tmp_path, model, monkeypatch):
    """With numba the sub-steps run compiled (a tick of 1 s is 40 000 of them); without it
    NumPy computes them: the same values and spikes, tick by tick."""
    pytest.importorskip("numba")
    from ikaros.modules.brain import _conductance_kernels

    def trace():
        with load(tmp_path, '<module class="Constant" name="I" data="0,5,10,40"/>'
                            f'<module class="ConductanceNeuronPopulation" name="N" '
                            f'model="{model}" population_size="4"/>'
                            '<connection source="I.OUTPUT" target="N.CURRENT" delay="0"/>',
                  tick_duration="0.01") as net:
            rows = []
            for _ in range(4):
                net.step()
                rows.append(np.concatenate([net.output(f"N.{o}") for o in
                                            ("VOLTAGE", "RECOVERY", "SPIKE_COUNT")]))
            return np.array(rows)

    assert _conductance_kernels.kernels() is not None
    compiled = trace()
    monkeypatch.setattr(_conductance_kernels, "_kernels", [None])
    numpy_form = trace()
    np.testing.assert_array_equal(compiled, numpy_form)
    if model == "hodgkin_huxley":           # the undriven neuron rests, the driven ones fire
        spikes = compiled[:, 8:].sum(axis=0)
        assert spikes[0] == 0 and spikes[3] > spikes[2] > 0
