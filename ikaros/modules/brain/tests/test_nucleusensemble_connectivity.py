"""NucleusEnsemble with topologies as data (issue 30): weight files, random topologies and
sparse products, against the ensemble's equation in NumPy."""
import math

import numpy as np
import pytest

from ikaros.testing import load_body, matrix_text


def f(x):
    return np.arctan(np.maximum(x, 0)) / math.tan(1)      # Ikaros 2's scaledsigmoid


def run(tmp_path, params, excitation, ticks=15):
    net = load_body(tmp_path, f'<module class="NucleusEnsemble" name="N" {params}/>'
                    f'<module class="Constant" name="E" data="{matrix_text(excitation)}"/>'
                    '<connection source="E.OUTPUT" target="N.EXCITATION" delay="0"/>')
    try:
        rows = []
        for _ in range(ticks):
            net.step()
            rows.append(net.output("N.OUTPUT").astype(np.float64))
        return np.array(rows)
    finally:
        net.close()


def expected(w, e, scale, ticks=15, epsilon=0.1):
    """a = W e (divided by the synapses onto each nucleus with scale), x += epsilon (a - x),
    OUTPUT = f(x) while a >= 0 (threshold 0, the tetanus is a)."""
    a = w @ e
    if scale:
        count = np.count_nonzero(w, axis=1)
        a = np.divide(a, count, out=np.zeros_like(a), where=count > 0)
    x, rows = np.zeros(len(w)), []
    for _ in range(ticks):
        x += epsilon * (a - x)
        rows.append(np.where(a >= 0, f(x), 0.0))
    return np.array(rows)


W = np.array([[0.5, 0.0, 0.0, 1.5], [0.0, 0.0, 0.0, 0.0], [0.25, 2.0, 0.0, 0.0]])
E = np.array([1.0, 2.0, 3.0, 0.5])


@pytest.mark.parametrize("scale", ["yes", "no"])
@pytest.mark.parametrize("storage", ["dense", "sparse"])
@pytest.mark.parametrize("form", ["npy", "npz", "csv"])
def test_weight_file_replaces_the_topology(tmp_path, scale, storage, form):
    if form == "npy":
        np.save(tmp_path / "w.npy", W)
    elif form == "csv":
        np.savetxt(tmp_path / "w.csv", W, delimiter=",")
    else:
        rows, cols = np.nonzero(W)
        np.savez(tmp_path / "w.npz", row=rows, col=cols, data=W[rows, cols], shape=W.shape)
    got = run(tmp_path, f'size="3" scale="{scale}" synapse_storage="{storage}" '
              f'excitation_weights_file="w.{form}" excitation_topology="all_to_all"', E)
    assert np.allclose(got, expected(W, E, scale == "yes"), atol=1e-6)


def test_random_topology(tmp_path):
    n, m = 40, 30
    e = np.linspace(0.1, 3.0, m)
    full = run(tmp_path, f'size="{n}" excitation_topology="random" '
               'connection_probability="1" scale="no"', e)
    assert np.allclose(full, expected(np.ones((n, m)), e, False), atol=1e-6)
    none = run(tmp_path, f'size="{n}" excitation_topology="random" '
               'connection_probability="0"', e)
    assert np.all(none == 0)
    some = [run(tmp_path, f'size="{n}" excitation_topology="random" seed="{s}" '
                'connection_probability="0.2" scale="no"', e) for s in (3, 3, 4)]
    assert np.array_equal(some[0], some[1]) and not np.array_equal(some[0], some[2])
    # about a fifth of the inputs reach each nucleus: the drive is near 0.2 sum(e)
    drive = np.tan(some[0][-1] * math.tan(1)) / (1 - 0.9 ** 15)
    assert 0.1 * e.sum() < drive.mean() < 0.3 * e.sum()


def test_large_sparse_topology_uses_the_same_numbers(tmp_path):
    """A 600 x 600 one-to-one topology (360,000 pairs, 0.2 % connected) is kept sparse by
    auto and gives what dense storage gives."""
    e = np.linspace(-1.0, 2.0, 600)
    auto = run(tmp_path, 'size="600" excitation_topology="one_to_one"', e, ticks=5)
    dense = run(tmp_path, 'size="600" excitation_topology="one_to_one" '
                'synapse_storage="dense"', e, ticks=5)
    assert np.array_equal(auto, dense)
    assert np.allclose(auto, expected(np.eye(600), e, True, ticks=5), atol=1e-6)


def test_wrong_weight_file_shape_is_named(tmp_path):
    np.save(tmp_path / "w.npy", np.ones((2, 2)))
    with pytest.raises(Exception) as info:
        run(tmp_path, 'size="3" excitation_weights_file="w.npy"', E)
    assert "excitation_weights_file" in str(info.value) and "3 x 4" in str(info.value)


def test_sparse_storage_without_scipy_names_the_install(tmp_path, monkeypatch):
    """A sparse topology needs scipy: without it the load fails with the pip install that
    brings it; dense storage needs nothing more than NumPy."""
    import sys
    monkeypatch.setitem(sys.modules, "scipy.sparse", None)     # import fails
    with pytest.raises(Exception) as info:
        run(tmp_path, 'size="3" synapse_storage="sparse"', E[:3])
    assert "pip install 'ikaros[scipy]'" in str(info.value)
    got = run(tmp_path, 'size="3" synapse_storage="dense" scale="no"', E[:3])
    assert np.allclose(got, expected(np.eye(3), E[:3], False), atol=1e-6)
