"""The connectivity helper of the populations (_connectivity): projections made from a
probability, a matrix, triplets and files, and spikes added column by column."""
import numpy as np
import pytest

from ikaros.modules.neural import _connectivity as connectivity

W = np.array([[0.0, 1.5, 0.0], [2.0, 0.0, 0.0], [0.5, 0.25, 3.0], [0.0, 0.0, 0.0]])


def sparse_of(w):
    rows, cols = np.nonzero(w)
    return connectivity.from_triplets(rows, cols, w[rows, cols], w.shape)


def test_sparse_columns_hold_each_senders_synapses():
    p = sparse_of(W)
    assert not p.is_dense and p.synapse_count == 5
    assert list(p.indptr) == [0, 2, 4, 5]
    assert list(p.indices) == [1, 2, 0, 2, 2]
    assert list(p.data) == [2.0, 0.5, 1.5, 0.25, 3.0] and p.data.dtype == np.float32
    assert np.array_equal(p.to_dense(), W)
    assert np.array_equal(p.as_dense().dense, W) and np.array_equal(
        p.as_dense().as_sparse().to_dense(), W)


@pytest.mark.parametrize("compiled", [False, True])
@pytest.mark.parametrize("storage", ["dense", "sparse"])
def test_add_spikes_reads_only_the_senders_columns(storage, compiled):
    p = sparse_of(W) if storage == "sparse" else sparse_of(W).as_dense()
    out = np.zeros(4)
    p.add_spikes(out, np.array([0, 2]), compiled=compiled)
    assert list(out) == [0.0, 2.0, 3.5, 0.0]          # columns 0 and 2
    out = np.zeros(4)
    p.add_spikes(out, np.array([1, 2]), np.array([2.0, 4.0], np.float32), compiled)
    assert list(out) == [3.0, 0.0, 12.5, 0.0]         # 2 * column 1 + 4 * column 2
    p.add_spikes(out, np.array([], dtype=np.int64), compiled=compiled)
    assert list(out) == [3.0, 0.0, 12.5, 0.0]


def test_triplets_add_repeated_pairs_and_refuse_pairs_outside():
    p = connectivity.from_triplets([0, 0, 1], [1, 1, 0], [1.0, 2.0, 4.0], (2, 2))
    assert np.array_equal(p.to_dense(), [[0, 3], [4, 0]])
    with pytest.raises(ValueError, match="outside the 2 x 2 matrix"):
        connectivity.from_triplets([2], [0], [1.0], (2, 2))


def test_matrix_shape_is_checked():
    with pytest.raises(ValueError, match="have shape 4 x 3 but must be 3 x 4"):
        connectivity.from_matrix(W, (3, 4), "the weights")
    assert connectivity.from_matrix(W.ravel(), (4, 3)).shape == (4, 3)


def test_random_with_probability_one_draws_what_uniform_draws():
    p = connectivity.random(np.random.default_rng(7), (5, 6), 0.5, 1.5)
    expected = np.random.default_rng(7).uniform(0.5, 1.5, (5, 6)).astype(np.float32)
    assert p.is_dense and np.array_equal(p.to_dense(), expected)


@pytest.mark.parametrize("probability", [0.01, 0.1, 0.5])
def test_random_with_a_probability_draws_each_pair_with_it(probability):
    n_post, n_pre = 300, 400
    p = connectivity.random(np.random.default_rng(1), (n_post, n_pre), 2.0, 3.0, probability)
    w = p.to_dense()
    count = np.count_nonzero(w)
    mean, sd = probability * w.size, np.sqrt(w.size * probability * (1 - probability))
    assert abs(count - mean) < 5 * sd                 # binomial: within five deviations
    assert w[w > 0].min() >= 2.0 and w.max() < 3.0
    per_sender = np.count_nonzero(w, axis=0)          # senders alike, receivers alike
    assert abs(per_sender[:200].mean() - per_sender[200:].mean()) < 5 * sd / 200
    if not p.is_dense:
        assert all(np.all(np.diff(p.indices[a:b]) > 0) for a, b in zip(p.indptr, p.indptr[1:]))
    again = connectivity.random(np.random.default_rng(1), (n_post, n_pre), 2.0, 3.0,
                                probability)
    assert np.array_equal(again.to_dense(), w)


def test_random_refuses_a_probability_outside_0_1():
    with pytest.raises(ValueError, match="in 0..1"):
        connectivity.random(np.random.default_rng(), (2, 2), 0, 1, 1.5)


def test_files(tmp_path):
    np.savez(tmp_path / "bad.npz", format="dia", shape=(4, 3), data=np.zeros(1))
    with pytest.raises(ValueError, match="'dia' is not read"):
        connectivity.load(str(tmp_path / "bad.npz"), (4, 3))
    np.savez(tmp_path / "small.npz", row=[0], col=[0], data=[1.0], shape=(2, 2))
    with pytest.raises(ValueError, match="holds a 2 x 2 matrix but 4 x 3 is needed"):
        connectivity.load(str(tmp_path / "small.npz"), (4, 3))
    with pytest.raises(ValueError, match="does not exist"):
        connectivity.load(str(tmp_path / "none.npy"), (4, 3))
    # compressed sparse columns with unsorted receivers are sorted on reading
    np.savez(tmp_path / "csc.npz", format="csc", shape=(4, 3), indptr=[0, 2, 4, 5],
             indices=[2, 1, 2, 0, 2], data=[0.5, 2.0, 0.25, 1.5, 3.0])
    assert np.array_equal(connectivity.load(str(tmp_path / "csc.npz"), (4, 3)).to_dense(), W)


def test_a_scipy_sparse_matrix_is_taken_as_it_is():
    sparse = pytest.importorskip("scipy.sparse")
    p = connectivity.from_matrix(sparse.csr_matrix(W), (4, 3))
    assert not p.is_dense and np.array_equal(p.to_dense(), W)
    assert list(p.indptr) == [0, 2, 4, 5] and list(p.indices) == [1, 2, 0, 2, 2]
