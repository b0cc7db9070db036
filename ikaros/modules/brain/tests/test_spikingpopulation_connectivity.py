"""SpikingPopulation with connectivity as data (issue 30): the spikes of before, hand-computed
networks for each form of the weights, sparse and dense alike, time_step, spike_input."""
import json
import os

import numpy as np
import pytest

from ikaros.testing import load_body, matrix_text

from spiking_fixture_network import raster
from test_spikingpopulation import ABCD

HERE = os.path.dirname(__file__)
RS = ABCD["regular_spiking"]


def izhikevich(current, ticks, a, b, c, d, substeps=2, threshold=30.0, dt=1.0):
    """One neuron with a constant current, plain Python floats, dt ms per tick: the ticks
    of its spikes."""
    v, u = -65.0, b * -65.0
    spikes = []
    for t in range(ticks):
        if v >= threshold:
            v, u = c, u + d
        for _ in range(substeps):
            v = min(v + (dt / substeps) * (0.04 * v * v + 5.0 * v + 140.0 - u + current),
                    threshold)
        u += (dt * a) * (b * v - u)
        if v >= threshold:
            spikes.append(t)
    return spikes


def spike_ticks(tmp_path, body, population, ticks, **overrides):
    """The spike ticks of each neuron of ``population``."""
    net = load_body(tmp_path, body, **overrides)
    try:
        rows = []
        for _ in range(ticks):
            net.step()
            rows.append(net.output(f"{population}.OUTPUT") >= 30)
        rows = np.array(rows)
        return [list(np.flatnonzero(rows[:, i])) for i in range(rows.shape[1])]
    finally:
        net.close()


@pytest.mark.parametrize("kernel", ["auto", "numpy"])
def test_same_spikes_as_before_issue_30(tmp_path, kernel):
    """The seeded network of spiking_fixture_network.py gives the raster recorded with the
    code before connectivity became data (dense float64 weights), with the numba loops
    (when installed) and with NumPy alone. Rec.EXCITATION_IN takes two connections, laid
    end to end in declaration order then: concatenation="declared" keeps that."""
    with open(os.path.join(HERE, "data", "spiking_raster_before_issue30.json")) as f:
        expected = json.load(f)
    assert raster(tmp_path, spike_kernel=kernel, concatenation="declared") == expected


# --- a hand-computed network of three neurons --------------------------------------------
# Inputs held constant: EXCITATION_IN = [30, 0, 30, 40] (elements 0, 2 and 3 spike on every
# tick), INHIBITION_IN = [0, 30] (element 1 spikes). Weights are multiples of 1/8, exact in
# float32, so the currents below are exact.
W_EXC = np.array([[0.25, 0.5, 0.0, 0.0],
                  [0.0, 0.0, 0.375, 0.125],
                  [0.125, 0.0, 0.125, 0.25]])
W_INH = np.array([[0.0, 0.0], [0.0, 0.125], [0.0, 0.25]])
EXC_IN = [30.0, 0.0, 30.0, 40.0]
INH_IN = [0.0, 30.0]
DIRECT = [2.0, 3.0, 4.0]


def expected_currents(flag: bool):
    """I_i = DIRECT_i + sum_j W_exc[i, j] s_j - sum_k W_inh[i, k] s_k, plain Python, where
    s is the input's value (or 1 with flags) when it is at least 30, else 0."""
    def s(x):
        return (1.0 if flag else x) if x >= 30 else 0.0
    currents = []
    for i in range(3):
        total = DIRECT[i]
        total += sum(W_EXC[i][j] * s(EXC_IN[j]) for j in range(4))
        total -= sum(W_INH[i][k] * s(INH_IN[k]) for k in range(2))
        currents.append(total)
    return currents


def hand_network(weights: str, extra: str = "") -> str:
    return ('<module class="Constant" name="D" data="2 3 4"/>'
            '<module class="Constant" name="E" data="30 0 30 40"/>'
            '<module class="Constant" name="I" data="0 30"/>'
            f'<module class="SpikingPopulation" name="P" population_size="3" {weights} '
            f'{extra}/>'
            '<connection source="D.OUTPUT" target="P.DIRECT_IN" delay="0"/>'
            '<connection source="E.OUTPUT" target="P.EXCITATION_IN" delay="0"/>'
            '<connection source="I.OUTPUT" target="P.INHIBITION_IN" delay="0"/>')


def write_weight_files(folder, form):
    """The two weight matrices in the files of one form; returns the attributes naming them."""
    names = {}
    for kind, w in (("excitation", W_EXC), ("inhibition", W_INH)):
        name = os.path.join(str(folder), f"{kind}.{form.split('-')[0]}")
        if form == "npy":
            np.save(name, w)
        elif form == "csv":
            np.savetxt(name, w, delimiter=",")
        elif form == "txt":
            np.savetxt(name, w)
        elif form == "npz-coo":            # triplets written with NumPy alone
            rows, cols = np.nonzero(w)
            np.savez(name, row=rows, col=cols, data=w[rows, cols], shape=w.shape)
        else:                              # npz-csr, npz-csc: scipy.sparse.save_npz
            sparse = pytest.importorskip("scipy.sparse")
            matrix = sparse.csr_matrix(w) if form == "npz-csr" else sparse.csc_matrix(w)
            sparse.save_npz(name, matrix)
        names[kind] = os.path.basename(name)
    return (f'excitation_weights_file="{names["excitation"]}" '
            f'inhibition_weights_file="{names["inhibition"]}"')


FORMS = ["parameter", "npy", "csv", "txt", "npz-coo", "npz-csr", "npz-csc"]


@pytest.mark.parametrize("form", FORMS)
@pytest.mark.parametrize("spike_input", ["value", "flag"])
def test_hand_computed_network_for_each_form(tmp_path, form, spike_input):
    if form == "parameter":
        weights = (f'excitation_weights="{matrix_text(W_EXC)}" '
                   f'inhibition_weights="{matrix_text(W_INH)}"')
    else:
        weights = write_weight_files(tmp_path, form)
    got = spike_ticks(tmp_path, hand_network(weights, f'spike_input="{spike_input}"'), "P",
                      300)
    currents = expected_currents(spike_input == "flag")
    for i in range(3):
        assert got[i] == izhikevich(currents[i], 300, *RS), (i, currents[i])
    assert sum(len(g) for g in got) > 0


def test_hand_computed_network_from_probability_and_seed(tmp_path):
    """Probability 1 with equal bounds gives every synapse the same weight; probability 0
    gives none, so only DIRECT_IN drives the neurons."""
    full = 'synapse_min="0.125" synapse_max="0.125" inhibition_synapse_range="0.25 0.25"'
    got = spike_ticks(tmp_path, hand_network(full, 'seed="4"'), "P", 300)
    for i in range(3):
        current = DIRECT[i] + 0.125 * (30 + 30 + 40) - 0.25 * 30
        assert got[i] == izhikevich(current, 300, *RS)
    none = 'excitation_probability="0" inhibition_probability="0" seed="4"'
    got = spike_ticks(tmp_path, hand_network(none), "P", 300)
    assert got == [izhikevich(DIRECT[i], 300, *RS) for i in range(3)]


def recurrent_network(tmp_path, n, w, attrs, spike_input="flag"):
    """n neurons with direct currents 0..8 and recurrent synapses of weights w."""
    rows, cols = np.nonzero(w)
    np.savez(tmp_path / "w.npz", row=rows, col=cols, data=w[rows, cols], shape=w.shape)
    direct = matrix_text(np.linspace(0.0, 8.0, n), "g")
    return (f'<module class="Constant" name="D" data="{direct}"/>'
            f'<module class="SpikingPopulation" name="P" population_size="{n}" '
            f'spike_input="{spike_input}" {attrs}/>'
            '<connection source="D.OUTPUT" target="P.DIRECT_IN" delay="0"/>'
            '<connection source="P.OUTPUT" target="P.EXCITATION_IN" delay="1"/>')


def test_sparse_and_dense_storage_give_the_same_spikes(tmp_path):
    """A recurrent population of 40 neurons with 30 % of its synapses, weights multiples of
    1/8 (so every order of summing is exact), stored dense and by sender, from the matrix
    parameter and from a file of triplets."""
    rng = np.random.default_rng(12)
    n = 40
    w = np.where(rng.random((n, n)) < 0.3, rng.integers(1, 5, (n, n)) / 8.0, 0.0)
    rasters = [spike_ticks(tmp_path, recurrent_network(tmp_path, n, w, f'{source} '
                                                       f'synapse_storage="{storage}"'),
                           "P", 400)
               for source in (f'excitation_weights="{matrix_text(w)}"',
                              'excitation_weights_file="w.npz"')
               for storage in ("dense", "sparse")]
    assert all(r == rasters[0] for r in rasters[1:])
    alone = spike_ticks(tmp_path, recurrent_network(tmp_path, n, w, 'excitation_probability'
                                                    '="0"'), "P", 400)
    assert rasters[0] != alone               # the recurrent synapses matter


@pytest.mark.parametrize("storage", ["dense", "sparse"])
@pytest.mark.parametrize("spike_input", ["value", "flag"])
def test_numba_and_numpy_add_the_same_numbers(tmp_path, storage, spike_input):
    """Weights that are not exact in float32 sums: the compiled loop and NumPy add them in
    the same order, so the membrane potentials agree to the bit."""
    pytest.importorskip("numba")
    rng = np.random.default_rng(3)
    n = 30
    w = np.where(rng.random((n, n)) < 0.5, rng.uniform(0.0, 0.04, (n, n)), 0.0)
    if spike_input == "flag":
        w *= 30.0
    out = {}
    for kernel in ("auto", "numpy"):
        net = load_body(tmp_path, recurrent_network(
            tmp_path, n, w, f'excitation_weights_file="w.npz" synapse_storage="{storage}" '
            f'spike_kernel="{kernel}"', spike_input))
        try:
            out[kernel] = []
            for _ in range(300):
                net.step()
                out[kernel].append(net.output("P.OUTPUT").copy())
        finally:
            net.close()
    assert np.array_equal(out["auto"], out["numpy"])
    assert np.sum(np.array(out["auto"]) >= 30) > 50


@pytest.mark.parametrize("dt", [0.5, 0.25])
def test_time_step_follows_tick_duration(tmp_path, dt):
    """time_step 0 takes the kernel's tick_duration (seconds) as the model's time step (ms);
    a time_step of the same length gives the same spikes."""
    body = ('<module class="Constant" name="C" data="6 12"/>'
            '<module class="SpikingPopulation" name="P" population_size="2" {}/>'
            '<connection source="C.OUTPUT" target="P.DIRECT_IN" delay="0"/>')
    follow = spike_ticks(tmp_path, body.format('time_step="0"'), "P", 800,
                         tick_duration=str(dt / 1000))
    fixed = spike_ticks(tmp_path, body.format(f'time_step="{dt}"'), "P", 800)
    assert follow == fixed
    for i, current in enumerate([6.0, 12.0]):
        assert follow[i] == izhikevich(current, 800, *RS, dt=dt)
    one_ms = spike_ticks(tmp_path, body.format(""), "P", 800)
    assert len(one_ms[1]) > len(follow[1])   # shorter ticks: fewer spikes per tick count


@pytest.mark.parametrize("attrs, message", [
    ('excitation_weights="1 2; 3 4"', "excitation_weights have shape 2 x 2 but must be 3 x 4"),
    ('inhibition_weights_file="missing.npy"', "inhibition_weights_file"),
    ('inhibition_synapse_range="1 2 3"', "inhibition_synapse_range has 3 values"),
])
def test_bad_weights_are_named(tmp_path, attrs, message):
    with pytest.raises(Exception) as info:
        load_body(tmp_path, hand_network(attrs)).close()
    assert message in str(info.value)
