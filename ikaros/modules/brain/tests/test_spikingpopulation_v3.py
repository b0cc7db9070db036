"""Tests of SpikingPopulation's Ikaros 3 inputs (EXCITATION, INHIBITION, EXCITATION_TOPOLOGY,
INTERNAL_TOPOLOGY) and parameters, against an Izhikevich population written out here."""
import numpy as np
import pytest

import ikaros
from ikaros.testing import load_body as load

A, B, C, D = 0.02, 0.2, -65.0, 8.0           # regular spiking (Izhikevich 2003)


def reference(ticks, n, direct=None, inputs=(), internal=None, threshold=30.0):
    """v of every tick: ``inputs`` are (spike values, weights) pairs, values at or above the
    threshold being spikes that add weight times value; ``internal`` feeds back the
    previous tick's spikes (their value is the threshold)."""
    v, u = np.full(n, -65.0), np.full(n, B * -65.0)
    out = []
    for _ in range(ticks):
        current = np.zeros(n) if direct is None else np.array(direct, float)
        for values, weights in inputs:
            values = np.asarray(values, float)
            spiking = values >= threshold
            current += np.asarray(weights, float)[:, spiking] @ values[spiking]
        if internal is not None:
            fired = v >= threshold
            current += np.asarray(internal, float)[:, fired] @ v[fired]
        fired = v >= threshold
        v[fired] = C
        u[fired] += D
        for _ in range(2):
            v = np.minimum(v + 0.5 * (0.04 * v * v + 5 * v + 140 - u + current), threshold)
        u += A * (B * v - u)
        out.append(v.copy())
    return np.array(out)


def run(tmp_path, body, ticks, **kw):
    net = load(tmp_path, body, **kw)
    try:
        out = []
        for _ in range(ticks):
            net.step()
            out.append(net.output("P.OUTPUT").copy())
        return np.array(out)
    finally:
        net.close()


def test_excitation_topology_gives_the_weights(tmp_path):
    weights = [[0.2, 5, 0.3], [0, 9, 0.05]]
    body = ('<module class="Constant" name="S" data="30 0 31"/>'
            '<module class="Constant" name="W" data="0.2 5 0.3; 0 9 0.05"/>'
            '<module class="SpikingPopulation" name="P" population_size="2"/>'
            '<connection source="S.OUTPUT" target="P.EXCITATION" delay="0"/>'
            '<connection source="W.OUTPUT" target="P.EXCITATION_TOPOLOGY" delay="0"/>')
    got = run(tmp_path, body, 100)
    expected = reference(100, 2, inputs=[([30, 0, 31], weights)])
    assert np.allclose(got, expected, atol=1e-3)
    # by hand: 30 * 0.2 + 31 * 0.3 = 15.3 and 31 * 0.05 = 1.55: one fires, one does not
    assert (got[:, 0] >= 30).any() and not (got[:, 1] >= 30).any()


def test_internal_topology_feeds_back_the_spikes(tmp_path):
    body = ('<module class="Constant" name="I" data="12 0 0"/>'
            '<module class="Constant" name="W" data="0 0 0; 0.6 0 0; 0 -1 0"/>'
            '<module class="SpikingPopulation" name="P" population_size="3"/>'
            '<connection source="I.OUTPUT" target="P.DIRECT_IN" delay="0"/>'
            '<connection source="W.OUTPUT" target="P.INTERNAL_TOPOLOGY" delay="0"/>')
    got = run(tmp_path, body, 200)
    internal = [[0, 0, 0], [0.6, 0, 0], [0, -1, 0]]
    expected = reference(200, 3, direct=[12, 0, 0], internal=internal)
    assert np.allclose(got, expected, atol=1e-3)
    assert (got[:, 1] >= 30).any()            # driven only through neuron 0's spikes


def test_ikaros3_names_are_the_ikaros2_inputs(tmp_path):
    def body(exc, inh):
        return ('<module class="Constant" name="S" data="30 40 0"/>'
                '<module class="Constant" name="T" data="35 0"/>'
                '<module class="SpikingPopulation" name="P" population_size="4" seed="3" '
                'synapse_min="2" synapse_max="6"/>'
                f'<connection source="S.OUTPUT" target="P.{exc}" delay="0"/>'
                f'<connection source="T.OUTPUT" target="P.{inh}" delay="0"/>')
    v2 = run(tmp_path, body("EXCITATION_IN", "INHIBITION_IN"), 50)
    v3 = run(tmp_path, body("EXCITATION", "INHIBITION"), 50)
    assert np.array_equal(v2, v3) and (v2 >= 30).any()


def test_wrong_topology_shapes_and_both_names_are_errors(tmp_path):
    with pytest.raises(ikaros.ModelError, match="INTERNAL_TOPOLOGY has shape"):
        load(tmp_path, '<module class="Constant" name="W" data="1 2; 3 4"/>'
                       '<module class="SpikingPopulation" name="P" population_size="3"/>'
                       '<connection source="W.OUTPUT" target="P.INTERNAL_TOPOLOGY"/>')
    with pytest.raises(ikaros.ModelError, match="not both"):
        load(tmp_path, '<module class="Constant" name="S" data="1 2"/>'
                       '<module class="SpikingPopulation" name="P" population_size="3"/>'
                       '<connection source="S.OUTPUT" target="P.EXCITATION"/>'
                       '<connection source="S.OUTPUT" target="P.EXCITATION_IN"/>')


def test_ikaros3_defaults_and_debugmode(tmp_path, capsys):
    net = load(tmp_path, '<module class="Constant" name="I" data="20"/>'
                         '<module class="SpikingPopulation" name="P" debugmode="yes"/>'
                         '<connection source="I.OUTPUT" target="P.DIRECT_IN"/>', dialect="3")
    try:
        assert net.output("P.OUTPUT").shape == (1,)          # population_size 1
        net.run(ticks=3)
    finally:
        net.close()
    assert capsys.readouterr().out.count("spikes") == 3
