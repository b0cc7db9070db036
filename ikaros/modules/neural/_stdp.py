"""Pair-based STDP with traces on the synapses of a sparse projection (``_connectivity``).

Each sender j has a trace x_j and each receiver i a trace y_i; both decay by exp(-dt/tau)
every tick (tau_plus for x, tau_minus for y) and grow by 1 on a spike. When sender j spikes,
every synapse w_ij of it loses a_minus * y_i (a receiver that spiked before: depression);
when receiver i spikes, every synapse w_ij onto it gains a_plus * x_j (a sender that spiked
before or on the same tick: potentiation). Weights stay in 0..w_max.
"""
from __future__ import annotations

import math

import numpy as np

from ._connectivity import Projection, runs


class STDP:
    """The traces and the rule for one projection, stored by sender (its ``data`` is
    changed in place) with a second index by receiver."""

    def __init__(self, projection: Projection, a_plus: float, a_minus: float,
                 tau_plus: float, tau_minus: float, w_max: float):
        if projection.is_dense:
            raise ValueError("STDP needs a sparse projection")
        for name, tau in (("stdp_tau_plus", tau_plus), ("stdp_tau_minus", tau_minus)):
            if not tau > 0:
                raise ValueError(f"{name} must be > 0, not {tau}")
        self.projection = projection
        self.a_plus, self.a_minus = float(a_plus), float(a_minus)
        self.tau_plus, self.tau_minus = float(tau_plus), float(tau_minus)
        self.w_max = float(w_max)
        n_post, n_pre = projection.shape
        self.pre_trace = np.zeros(n_pre)
        self.post_trace = np.zeros(n_post)
        counts = np.diff(projection.indptr)
        self._sender_of = np.repeat(np.arange(n_pre, dtype=np.int32), counts)
        self._by_receiver = np.argsort(projection.indices, kind="stable")
        self._receiver_ptr = np.zeros(n_post + 1, dtype=np.int64)
        np.cumsum(np.bincount(projection.indices, minlength=n_post),
                  out=self._receiver_ptr[1:])

    def decay(self, dt: float) -> None:
        """The traces decay over one tick of dt (the unit of the time constants)."""
        self.pre_trace *= math.exp(-dt / self.tau_plus)
        self.post_trace *= math.exp(-dt / self.tau_minus)

    def on_pre(self, senders: np.ndarray) -> None:
        """Senders spiked: depress their synapses by a_minus * y, then count the spikes."""
        p = self.projection
        positions = runs(p.indptr, senders)
        if positions.size:
            w = p.data[positions] - self.a_minus * self.post_trace[p.indices[positions]]
            p.data[positions] = np.clip(w, 0.0, self.w_max)
        self.pre_trace[senders] += 1.0

    def on_post(self, receivers: np.ndarray) -> None:
        """Receivers spiked: count the spikes, then potentiate their synapses by a_plus * x."""
        self.post_trace[receivers] += 1.0
        positions = self._by_receiver[runs(self._receiver_ptr, receivers)]
        if positions.size:
            p = self.projection
            w = p.data[positions] + self.a_plus * self.pre_trace[self._sender_of[positions]]
            p.data[positions] = np.clip(w, 0.0, self.w_max)

