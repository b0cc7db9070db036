"""Compiled loops of spiking populations, with numba (the optional extra ``ikaros[fast]``).

``kernels()`` gives them, or None when numba is not installed; the callers then use their
NumPy forms, which compute the same numbers in the same order (so both give the same
spikes). numba is imported on the first call only (it takes about a second), as the
kernel's compiled tick does, so that classes that never ask for the loops do not pay for it.
"""
from __future__ import annotations

import numpy as np


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


def _izhikevich(v, u, current, a, b, c, d, threshold, steps, h, dt_a, output, spiking):
    """One tick of Izhikevich neurons, neuron by neuron, with the operations of
    SpikingPopulation's NumPy form in the same order; the indices of the neurons that spike
    go to ``spiking``; returns their number."""
    count = 0
    for i in range(v.size):
        vi, ui = v[i], u[i]
        if vi >= threshold:
            vi = c
            ui += d
        for _ in range(steps):
            vi += h * (0.04 * vi * vi + 5.0 * vi + 140.0 - ui + current[i])
            if vi > threshold:
                vi = threshold
        ui += dt_a * (b * vi - ui)
        v[i], u[i] = vi, ui
        output[i] = vi
        if vi >= threshold:
            spiking[count] = i
            count += 1
    return count


class Kernels:
    """The loops compiled by numba."""

    def __init__(self, numba):
        jit = numba.njit(cache=True, nogil=True)
        self.add_sparse = jit(_add_sparse)
        self.add_dense = jit(_add_dense)
        self.izhikevich = jit(_izhikevich)

    def warm_up(self) -> None:
        """Compile (or load from numba's cache) every loop for the argument types the
        populations pass, so that the first tick does not pay for it."""
        f32, f64, i64 = np.float32, np.float64, np.int64
        one, none = np.zeros(1, i64), np.zeros(0, f32)
        for values in (none, np.ones(1, f32)):
            self.add_sparse(np.array([0, 1], i64), np.zeros(1, np.int32), np.ones(1, f32),
                            one, values, np.zeros(1, f64))
            self.add_dense(np.ones((1, 1), f32, order="F"), one, values, np.zeros(1, f64))
        self.izhikevich(np.zeros(1), np.zeros(1), np.zeros(1), 0.02, 0.2, -65.0, 8.0, 30.0,
                        2, 0.5, 0.02, np.zeros(1, f32), np.zeros(1, i64))


_kernels: list = []


def kernels() -> Kernels | None:
    """The compiled loops, made (or loaded from numba's cache) on the first call; None
    when numba is not installed."""
    if not _kernels:
        try:
            import numba
        except ImportError:          # numba is optional: the NumPy forms are used instead
            _kernels.append(None)
        else:
            made = Kernels(numba)
            made.warm_up()
            _kernels.append(made)
    return _kernels[0]
