"""Tests of SpikingPopulation: firing follows the input current as the Izhikevich model says."""
import numpy as np
import pytest

from ikaros.testing import load_body as load

ABCD = {"regular_spiking": (0.02, 0.2, -65.0, 8.0), "fast_spiking": (0.1, 0.2, -65.0, 2.0),
        "chattering": (0.02, 0.2, -50.0, 2.0)}


def izhikevich(current, ticks, a, b, c, d, substeps=2, threshold=30.0):
    """One neuron, plain Python floats: returns the ticks on which it spikes."""
    v, u = -65.0, b * -65.0
    spikes = []
    for t in range(ticks):
        if v >= threshold:
            v, u = c, u + d
        for _ in range(substeps):
            v = min(v + (1.0 / substeps) * (0.04 * v * v + 5.0 * v + 140.0 - u + current),
                    threshold)
        u += a * (b * v - u)
        if v >= threshold:
            spikes.append(t)
    return spikes


def run(tmp_path, currents, ticks, neuron_type="regular_spiking", extra=""):
    data = " ".join(str(c) for c in currents)
    net = load(tmp_path, f'<module class="Constant" name="C" data="{data}"/>'
               f'<module class="SpikingPopulation" name="P" population_size="{len(currents)}" '
               f'neuron_type="{neuron_type}" {extra}/>'
               '<connection source="C.OUTPUT" target="P.DIRECT_IN" delay="0"/>')
    try:
        spikes = np.zeros((ticks, len(currents)), bool)
        adenosine = np.zeros(ticks)
        for t in range(ticks):
            net.step()
            spikes[t] = net.output("P.OUTPUT") >= 30
            adenosine[t] = net.output("P.ADENOSINE")[0]
            assert np.all(net.output("P.OUTPUT") <= 30)
        return spikes, adenosine
    finally:
        net.close()


CURRENTS = [0.0, 2.0, 3.0, 5.0, 10.0, 20.0, 40.0]


@pytest.mark.parametrize("neuron_type", list(ABCD))
def test_rate_follows_current(tmp_path, neuron_type):
    spikes, adenosine = run(tmp_path, CURRENTS, 1000, neuron_type)
    counts = spikes.sum(axis=0)
    # below the rheobase (I = 4 for b = 0.2: 0.16 (140 + I) = (5 - b)^2) the neuron is silent
    assert list(counts[:3]) == [0, 0, 0]
    # above it, more current gives strictly more spikes, and the firing is sustained
    assert np.all(np.diff(counts[3:]) > 0) and counts[3] > 0
    assert np.all(spikes[500:, 3:].sum(axis=0) > 0)
    # each neuron matches the same equations computed independently, spike for spike
    for i, current in enumerate(CURRENTS):
        expected = izhikevich(current, 1000, *ABCD[neuron_type])
        assert list(np.flatnonzero(spikes[:, i])) == expected, current
    # ADENOSINE counts the spikes of each tick
    assert np.array_equal(adenosine, spikes.sum(axis=1))


def test_fast_spiking_fires_faster_than_regular(tmp_path):
    rs = run(tmp_path, [10.0], 500)[0].sum()
    fs = run(tmp_path, [10.0], 500, "fast_spiking")[0].sum()
    assert fs > 2 * rs > 0


def test_substeps_and_adenosine_factor(tmp_path):
    spikes, adenosine = run(tmp_path, [10.0, 15.0], 300, extra='substeps="4" '
                            'adenosine_factor="0.5"')
    for i, current in enumerate([10.0, 15.0]):
        expected = izhikevich(current, 300, *ABCD["regular_spiking"], substeps=4)
        assert list(np.flatnonzero(spikes[:, i])) == expected
    assert np.allclose(adenosine, 0.5 * spikes.sum(axis=1))


def test_short_direct_input_drives_only_the_first_neurons(tmp_path):
    net = load(tmp_path, '<module class="Constant" name="C" data="20"/>'
               '<module class="SpikingPopulation" name="P" population_size="3"/>'
               '<connection source="C.OUTPUT" target="P.DIRECT_IN" delay="0"/>')
    try:
        counts = np.zeros(3)
        for _ in range(200):
            net.step()
            counts += net.output("P.OUTPUT") >= 30
        assert counts[0] == len(izhikevich(20.0, 200, *ABCD["regular_spiking"]))
        assert counts[1] == counts[2] == 0
    finally:
        net.close()


def test_unconnected_population_rests(tmp_path):
    net = load(tmp_path, '<module class="SpikingPopulation" name="P" population_size="4"/>')
    try:
        assert np.all(net.output("P.OUTPUT") == -65)
        net.run(ticks=200)
        v = net.output("P.OUTPUT")
        assert np.all(v < -60) and np.all(np.isfinite(v))
        assert net.output("P.ADENOSINE")[0] == 0
    finally:
        net.close()


def test_synaptic_excitation_and_inhibition(tmp_path):
    """A driven population excites a second one through seeded random synapses. A third gets
    a direct current of 8 and a spike on every tick (30) through inhibitory synapses of
    weight 0.2..0.3, which removes 6..9 of the current: it stays silent, unlike a reference
    population without the inhibition."""
    body = ('<module class="Constant" name="C" data="15 15 15 15 15"/>'
            '<module class="Constant" name="D" data="8 8 8"/>'
            '<module class="Constant" name="Tonic" data="30 29"/>'
            '<module class="SpikingPopulation" name="Src" population_size="5"/>'
            '<module class="SpikingPopulation" name="Exc" population_size="3" seed="1" '
            'synapse_min="20" synapse_max="30"/>'
            '<module class="SpikingPopulation" name="Inh" population_size="3" seed="2" '
            'synapse_min="0.2" synapse_max="0.3"/>'
            '<module class="SpikingPopulation" name="Ref" population_size="3"/>'
            '<connection source="C.OUTPUT" target="Src.DIRECT_IN" delay="0"/>'
            '<connection source="Src.OUTPUT" target="Exc.EXCITATION_IN" delay="0"/>'
            '<connection source="D.OUTPUT" target="Inh.DIRECT_IN" delay="0"/>'
            '<connection source="Tonic.OUTPUT" target="Inh.INHIBITION_IN" delay="0"/>'
            '<connection source="D.OUTPUT" target="Ref.DIRECT_IN" delay="0"/>')
    net = load(tmp_path, body)
    try:
        counts = {k: np.zeros(3) for k in ("Src", "Exc", "Inh", "Ref")}
        for _ in range(500):
            net.step()
            for k in counts:
                counts[k][:] += (net.output(f"{k}.OUTPUT") >= 30)[:3]
        assert np.all(counts["Src"] > 0)
        assert np.all(counts["Exc"] > 0)          # driven only through the synapses
        assert np.all(counts["Ref"] > 0)
        assert np.all(counts["Inh"] == 0)         # 29 is below threshold: not a spike
    finally:
        net.close()


def test_same_seed_same_synapses(tmp_path):
    def spikes(seed):
        net = load(tmp_path, '<module class="Constant" name="C" data="15 15"/>'
                   '<module class="SpikingPopulation" name="Src" population_size="2"/>'
                   f'<module class="SpikingPopulation" name="P" population_size="6" '
                   f'seed="{seed}" synapse_min="0" synapse_max="2"/>'
                   '<connection source="C.OUTPUT" target="Src.DIRECT_IN" delay="0"/>'
                   '<connection source="Src.OUTPUT" target="P.EXCITATION_IN" delay="0"/>')
        try:
            out = []
            for _ in range(300):
                net.step()
                out.append(net.output("P.OUTPUT").copy())
            return np.array(out)
        finally:
            net.close()
    a, b, c = spikes(5), spikes(5), spikes(6)
    assert np.array_equal(a, b)
    assert not np.array_equal(a, c)
