"""Compiled loops for spike propagation, with numba (the optional extra ``ikaros[fast]``).

``KERNELS`` is None when numba is not installed; the callers then use their NumPy forms,
which add the same numbers in the same order (so both give the same spikes).
"""
from __future__ import annotations

try:
    import numba
except ImportError:          # numba is optional: the NumPy forms are used instead
    numba = None


def _add_sparse(indptr, indices, data, senders, values, out):
    """out[r] += data[k] (times the sender's value when values is not empty) for every
    synapse k of every sender, sender by sender, in order."""
    for n in range(senders.size):
        s = senders[n]
        if values.size:
            scale = values[n]               # float32, as the weights: a float32 product
            for k in range(indptr[s], indptr[s + 1]):
                out[indices[k]] += data[k] * scale
        else:
            for k in range(indptr[s], indptr[s + 1]):
                out[indices[k]] += data[k]


def _add_dense(weights, senders, values, out):
    """out[r] += weights[r, s] (times the sender's value) for every sender s, in order."""
    rows = weights.shape[0]
    for n in range(senders.size):
        s = senders[n]
        if values.size:
            scale = values[n]
            for r in range(rows):
                out[r] += weights[r, s] * scale
        else:
            for r in range(rows):
                out[r] += weights[r, s]


class _Kernels:
    def __init__(self):
        jit = numba.njit(cache=True, nogil=True)
        self.add_sparse = jit(_add_sparse)
        self.add_dense = jit(_add_dense)


KERNELS = _Kernels() if numba is not None else None
