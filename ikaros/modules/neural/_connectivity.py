"""Connectivity as data: the weights of one projection (receivers x senders), float32.

A projection is made from a connection probability with a seed (each receiver-sender pair is
a synapse with that probability, its weight uniform in a range), from a user weight matrix
(a parameter, or a file: .npy, a .npz written by ``scipy.sparse.save_npz`` or by
``numpy.savez`` with ``row``, ``col``, ``data`` and ``shape``, or a text/CSV file), or from
a sparse matrix. It is stored dense when more than a quarter of the pairs are synapses and
by sender (compressed sparse columns) otherwise, so that spikes are propagated by adding only the columns of the
senders that spiked: a tick costs in proportion to the spikes, not to receivers x senders.
Reading files needs only NumPy; ``product`` of a sparse projection with a rate vector uses
scipy.sparse.
"""
from __future__ import annotations

import os

import numpy as np

from ._spike_kernels import kernels

DENSE_ABOVE = 0.25      # a projection denser than this is stored as a dense matrix
_GAP_CHUNK = 1 << 22    # synapse positions drawn per round when sampling a sparse projection
_SENDER_BLOCK = 1024    # senders made dense at a time
_NO_VALUES = np.zeros(0, dtype=np.float32)


class Projection:
    """The weights W (receivers x senders, float32) of one projection.

    Dense: ``dense`` holds W with each sender's column contiguous. Sparse: the synapses of
    sender j are ``indices[indptr[j]:indptr[j+1]]`` (receivers, ascending) with the weights
    ``data[...]`` at the same places."""

    def __init__(self, shape: tuple[int, int], *, dense: np.ndarray | None = None,
                 indptr: np.ndarray | None = None, indices: np.ndarray | None = None,
                 data: np.ndarray | None = None):
        self.shape = (int(shape[0]), int(shape[1]))
        self.dense = None if dense is None else np.asfortranarray(dense, dtype=np.float32)
        if self.dense is None:
            self.indptr = np.asarray(indptr, dtype=np.int64)
            self.indices = np.asarray(indices, dtype=np.int32)
            self.data = np.asarray(data, dtype=np.float32)
        self._scipy_matrix = None

    # --- what it is ----------------------------------------------------------------------
    @property
    def is_dense(self) -> bool:
        return self.dense is not None

    @property
    def synapse_count(self) -> int:
        return int(np.count_nonzero(self.dense)) if self.is_dense else int(self.data.size)

    def as_sparse(self) -> "Projection":
        """This projection stored by sender (itself when it is already)."""
        return _sparse_from_dense(self.dense) if self.is_dense else self

    def as_dense(self) -> "Projection":
        """This projection stored dense (itself when it is already)."""
        return self if self.is_dense else Projection(self.shape,
                                                     dense=self._dense_by_sender().T)

    def to_dense(self) -> np.ndarray:
        """W as a dense float32 matrix (receivers x senders)."""
        if self.is_dense:
            return np.ascontiguousarray(self.dense)
        return np.ascontiguousarray(self._dense_by_sender().T)

    def _dense_by_sender(self) -> np.ndarray:
        """W transposed (senders x receivers, C order), filled a block of senders at a
        time so that no index array of all the synapses is made."""
        n_post, n_pre = self.shape
        w_t = np.zeros((n_pre, n_post), dtype=np.float32)
        flat = w_t.reshape(-1)
        for first in range(0, n_pre, _SENDER_BLOCK):
            last = min(first + _SENDER_BLOCK, n_pre)
            lo, hi = self.indptr[first], self.indptr[last]
            senders = np.repeat(np.arange(first, last, dtype=np.int64),
                                np.diff(self.indptr[first:last + 1]))
            flat[senders * n_post + self.indices[lo:hi]] = self.data[lo:hi]
        return w_t

    def stored_by_density(self) -> "Projection":
        """This projection stored dense when more than DENSE_ABOVE of the pairs are
        synapses, else by sender."""
        if not self.is_dense and self.data.size > DENSE_ABOVE * max(1, np.prod(self.shape)):
            return self.as_dense()
        return self

    # --- propagation ---------------------------------------------------------------------
    def add_spikes(self, out: np.ndarray, senders: np.ndarray,
                   values: np.ndarray | None = None, compiled: bool = False) -> None:
        """out += W[:, senders] @ values (values 1 when None; out float64): only the columns
        of the senders that spiked are read. Each weight (times its sender's value, in
        float32) is added in float64, sender by sender; with ``compiled`` (numba installed)
        a compiled loop does it, which gives the same numbers when out is zero on entry."""
        if senders.size == 0:
            return
        loops = kernels() if compiled else None
        if loops is not None:
            scale = _NO_VALUES if values is None else values.astype(np.float32)
            if self.is_dense:
                loops.add_dense(self.dense, senders, scale, out)
            else:
                loops.add_sparse(self.indptr, self.indices, self.data, senders, scale, out)
            return
        if self.is_dense:
            rows = self.dense.T[senders]              # one contiguous row per sender
            if values is not None:
                rows *= values.astype(np.float32)[:, None]
            out += rows.sum(axis=0, dtype=np.float64)   # row after row, in order
            return
        positions = runs(self.indptr, senders)
        if positions.size == 0:
            return
        weights = self.data[positions]
        if values is not None:
            counts = self.indptr[senders + 1] - self.indptr[senders]
            weights = weights * np.repeat(values.astype(np.float32), counts)
        out += np.bincount(self.indices[positions], weights=weights,
                           minlength=self.shape[0])

    def product(self, x: np.ndarray, sparse_module=None) -> np.ndarray:
        """W @ x (float64) for a rate input x; a sparse projection uses the scipy.sparse
        module passed in (``sparse_module``)."""
        if self.is_dense:
            return self.dense.astype(np.float64) @ x.astype(np.float64)
        if self._scipy_matrix is None:
            self._scipy_matrix = sparse_module.csc_matrix(
                (self.data.astype(np.float64), self.indices, self.indptr), shape=self.shape)
        return self._scipy_matrix @ x.astype(np.float64)


def runs(pointers: np.ndarray, which: np.ndarray) -> np.ndarray:
    """The positions pointers[k]..pointers[k+1]-1 of every k in ``which``, end to end (the
    synapses of the senders ``which`` when ``pointers`` is a projection's ``indptr``)."""
    starts = pointers[which]
    counts = pointers[which + 1] - starts
    total = int(counts.sum())
    if total == 0:
        return np.zeros(0, dtype=np.int64)
    return np.repeat(starts - np.cumsum(counts) + counts, counts) + np.arange(total)


# --- making projections ------------------------------------------------------------------
def from_matrix(w, shape: tuple[int, int] | None = None, where: str = "the weights"
                ) -> Projection:
    """A projection with the weights of a dense matrix (zeros are no synapse), or of any
    object with ``tocsc()`` (a scipy.sparse matrix)."""
    if hasattr(w, "tocsc"):
        csc = w.tocsc()
        csc.sort_indices()
        p = from_sparse(csc.indptr, csc.indices, csc.data, csc.shape)
    else:
        w = np.asarray(w, dtype=np.float32)
        if w.ndim == 1 and shape is not None and w.size == shape[0] * shape[1]:
            w = w.reshape(shape)
        if w.ndim != 2:
            raise ValueError(f"{where} must be a matrix, not an array of shape {w.shape}")
        nonzero = np.count_nonzero(w)
        p = (Projection(w.shape, dense=w) if nonzero > DENSE_ABOVE * max(1, w.size)
             else _sparse_from_dense(w))
    if shape is not None and p.shape != tuple(shape):
        raise ValueError(f"{where} have shape {p.shape[0]} x {p.shape[1]} but must be "
                         f"{shape[0]} x {shape[1]} (receivers x input elements)")
    return p


def _sparse_from_dense(w: np.ndarray) -> Projection:
    cols, rows = np.nonzero(w.T)                  # by sender, receivers ascending
    indptr = np.zeros(w.shape[1] + 1, dtype=np.int64)
    np.cumsum(np.bincount(cols, minlength=w.shape[1]), out=indptr[1:])
    return Projection(w.shape, indptr=indptr, indices=rows, data=w[rows, cols])


def from_sparse(indptr, indices, data, shape) -> Projection:
    """A projection from compressed sparse columns (receivers ascending in each column)."""
    return Projection(shape, indptr=indptr, indices=indices, data=data)


def from_triplets(rows, cols, data, shape) -> Projection:
    """A projection from (receiver, sender, weight) triplets; repeated pairs add up."""
    rows = np.asarray(rows, dtype=np.int64)
    cols = np.asarray(cols, dtype=np.int64)
    data = np.asarray(data, dtype=np.float64)
    n_post, n_pre = int(shape[0]), int(shape[1])
    if rows.size and (rows.min() < 0 or rows.max() >= n_post or cols.min() < 0
                      or cols.max() >= n_pre):
        raise ValueError(f"a synapse lies outside the {n_post} x {n_pre} matrix")
    key = cols * n_post + rows
    unique, inverse = np.unique(key, return_inverse=True)
    summed = np.bincount(inverse, weights=data, minlength=unique.size)
    indptr = np.zeros(n_pre + 1, dtype=np.int64)
    np.cumsum(np.bincount(unique // n_post, minlength=n_pre), out=indptr[1:])
    return Projection((n_post, n_pre), indptr=indptr, indices=unique % n_post, data=summed)


def random(rng: np.random.Generator, shape: tuple[int, int], low: float, high: float,
           probability: float = 1.0) -> Projection:
    """Each of the receivers x senders pairs is a synapse with ``probability``, its weight
    uniform in low..high. With probability 1 the weights are ``rng.uniform(low, high,
    shape)``, so a seed gives the weights it gave before connectivity became data."""
    n_post, n_pre = int(shape[0]), int(shape[1])
    if not 0.0 <= probability <= 1.0:
        raise ValueError(f"a connection probability must be in 0..1, not {probability}")
    if probability >= 1.0:
        return Projection((n_post, n_pre), dense=rng.uniform(low, high, (n_post, n_pre)))
    if probability > DENSE_ABOVE:
        positions = np.concatenate([np.zeros(0, np.int64), *_bernoulli_positions(
            rng, n_post * n_pre, probability)])
        w = np.zeros(n_post * n_pre, dtype=np.float32)
        w[positions] = _uniform_float32(rng, low, high, positions.size)
        return Projection((n_post, n_pre), dense=w.reshape(n_pre, n_post).T)
    counts = np.zeros(n_pre, dtype=np.int64)
    rows = []
    for positions in _bernoulli_positions(rng, n_post * n_pre, probability):
        cols, receivers = np.divmod(positions, n_post)   # positions run sender by sender
        counts += np.bincount(cols, minlength=n_pre)
        rows.append(receivers.astype(np.int32))
        del cols, receivers
    indices = np.concatenate([np.zeros(0, np.int32), *rows])
    del rows
    indptr = np.zeros(n_pre + 1, dtype=np.int64)
    np.cumsum(counts, out=indptr[1:])
    return Projection((n_post, n_pre), indptr=indptr, indices=indices,
                      data=_uniform_float32(rng, low, high, indices.size))


def _uniform_float32(rng: np.random.Generator, low: float, high: float, size: int
                     ) -> np.ndarray:
    """``rng.uniform(low, high, size)`` as float32, drawn a block at a time."""
    out = np.empty(size, dtype=np.float32)
    for first in range(0, size, _GAP_CHUNK):
        last = min(first + _GAP_CHUNK, size)
        out[first:last] = rng.uniform(low, high, last - first)
    return out


def _bernoulli_positions(rng: np.random.Generator, size: int, p: float):
    """The ascending positions in 0..size-1 chosen each with probability p, a block at a
    time: the gaps between them are geometric, so the cost is in proportion to the number
    chosen."""
    if p <= 0.0 or size == 0:
        return
    last = -1
    while last < size - 1:
        positions = last + np.cumsum(rng.geometric(p, _GAP_CHUNK))
        positions = positions[positions < size]
        if positions.size:
            yield positions
            last = int(positions[-1])
        if positions.size < _GAP_CHUNK:
            return


def load(filename: str, shape: tuple[int, int], where: str = "the weight file"
         ) -> Projection:
    """The projection in a file: .npy (a dense matrix), .npz (``scipy.sparse.save_npz``
    in csr, csc or coo format, or arrays ``row``, ``col``, ``data``, ``shape``) or text
    (.csv, .txt: rows of numbers separated by commas or spaces)."""
    if not os.path.isfile(filename):
        raise ValueError(f"{where} {filename!r} does not exist")
    ext = os.path.splitext(filename)[1].lower()
    try:
        if ext == ".npy":
            return from_matrix(np.load(filename, allow_pickle=False), shape, where)
        if ext == ".npz":
            return _load_npz(filename, shape, where).stored_by_density()
        with open(filename, encoding="utf-8") as f:
            text = f.read().replace(",", " ")
        rows = [line.split() for line in text.splitlines() if line.strip()]
        return from_matrix(np.array(rows, dtype=np.float64), shape, where)
    except (OSError, ValueError, KeyError) as e:
        raise ValueError(f"{where} {filename!r} cannot be read: {e}") from None


def _load_npz(filename: str, shape: tuple[int, int], where: str) -> Projection:
    with np.load(filename, allow_pickle=False) as z:
        file_shape = tuple(int(s) for s in z["shape"])
        if file_shape != tuple(shape):
            raise ValueError(f"it holds a {file_shape[0]} x {file_shape[1]} matrix but "
                             f"{shape[0]} x {shape[1]} is needed (receivers x input elements)")
        fmt = z["format"].item() if "format" in z else "coo"
        fmt = fmt.decode() if isinstance(fmt, bytes) else str(fmt)
        if fmt == "csc" and _sorted_columns(z["indptr"], z["indices"], shape[0]):
            return from_sparse(z["indptr"], z["indices"], z["data"], shape)
        if fmt in ("csr", "csc"):
            indptr, indices, data = z["indptr"], z["indices"], z["data"]
            n_major = file_shape[0] if fmt == "csr" else file_shape[1]
            major = np.repeat(np.arange(n_major), np.diff(indptr))
            rows, cols = (major, indices) if fmt == "csr" else (indices, major)
            return from_triplets(rows, cols, data, shape)
        if fmt == "coo":
            rows = z["row"] if "row" in z else z["coords"][0]
            cols = z["col"] if "col" in z else z["coords"][1]
            return from_triplets(rows, cols, z["data"], shape)
        raise ValueError(f"the sparse format {fmt!r} is not read (save it as csr, csc or "
                         f"coo)")


def _sorted_columns(indptr: np.ndarray, indices: np.ndarray, n_post: int) -> bool:
    """Whether compressed sparse columns hold each receiver at most once per column, in
    ascending order, and within 0..n_post-1 (checked a block at a time, so that no index
    array as long as the synapses is made)."""
    if indices.size == 0:
        return True
    if indptr[-1] != indices.size or np.any(np.diff(indptr) < 0):
        return False
    starts = np.zeros(indices.size, dtype=bool)        # where a column begins
    starts[indptr[:-1][indptr[:-1] < indices.size]] = True
    for first in range(0, indices.size, _GAP_CHUNK):
        block = indices[first:first + _GAP_CHUNK + 1]
        if block.min() < 0 or block.max() >= n_post:
            return False
        if not np.all((np.diff(block) > 0) | starts[first + 1:first + block.size]):
            return False
    return True
