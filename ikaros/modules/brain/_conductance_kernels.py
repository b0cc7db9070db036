"""Compiled sub-step loops of ConductanceNeuronPopulation, with numba (the optional extra
``ikaros[fast]``).

A tick of the default model is 40 000 Runge–Kutta sub-steps (tick_duration 1 s, sub-steps
of 25 µs); done with NumPy over the population that costs seconds a tick. These loops go
neuron by neuron through the same equations as ``_conductance.py`` with the same rounding
(float64 within a sub-step, the state stored as float32 after each), so both forms give
the same spikes; the last bits of a value may differ (libm's exp and pow against NumPy's).
``kernels()`` gives them, or None when numba is not installed: the caller then uses the
NumPy form. numba is imported on the first call only.
"""
from __future__ import annotations

import math

import numpy as np

# the order of the parameter vectors the loops take
HH_PARAMETERS = ("hh_capacitance_density", "hh_sodium_conductance", "hh_potassium_conductance",
                 "hh_leak_conductance", "hh_sodium_reversal_potential",
                 "hh_potassium_reversal_potential", "hh_leak_reversal_potential")
ML_PARAMETERS = ("ml_capacitance_density", "ml_calcium_conductance", "ml_potassium_conductance",
                 "ml_leak_conductance", "ml_calcium_reversal_potential",
                 "ml_potassium_reversal_potential", "ml_leak_reversal_potential",
                 "ml_activation_midpoint", "ml_activation_slope", "ml_recovery_midpoint",
                 "ml_recovery_slope", "ml_recovery_time_constant")


def _hodgkin_huxley(voltage, gates, current, g_e, g_i, e_e, e_i, p, steps, dt, threshold,
                    count):
    """``steps`` sub-steps of every neuron; spikes are added to ``count``."""
    def vtrap(x, s):
        if abs(x / s) < 1e-6:
            return s * (1 + x / (2 * s))
        return x / (1 - math.exp(-x / s))

    def derivatives(V, m, h, n, drive, ge, gi):
        am, bm = 0.1 * vtrap(V + 40, 10), 4 * math.exp(-(V + 65) / 18)
        ah, bh = 0.07 * math.exp(-(V + 65) / 20), 1 / (1 + math.exp(-(V + 35) / 10))
        an, bn = 0.01 * vtrap(V + 55, 10), 0.125 * math.exp(-(V + 65) / 80)
        ionic = (p[1] * m ** 3 * h * (V - p[4]) + p[2] * n ** 4 * (V - p[5])
                 + p[3] * (V - p[6]))
        synaptic = ge * (e_e - V) + gi * (e_i - V)
        return (1000 * (drive + synaptic - ionic) / p[0], 1000 * (am * (1 - m) - bm * m),
                1000 * (ah * (1 - h) - bh * h), 1000 * (an * (1 - n) - bn * n))

    half = dt / 2
    sixth = dt / 6
    for i in range(voltage.size):
        drive, ge, gi = current[i], g_e[i], g_i[i]
        for _ in range(steps):
            V, m, h, n = (np.float64(voltage[i]), np.float64(gates[0, i]),
                          np.float64(gates[1, i]), np.float64(gates[2, i]))
            a = derivatives(V, m, h, n, drive, ge, gi)
            b = derivatives(V + half * a[0], m + half * a[1], h + half * a[2],
                            n + half * a[3], drive, ge, gi)
            c = derivatives(V + half * b[0], m + half * b[1], h + half * b[2],
                            n + half * b[3], drive, ge, gi)
            d = derivatives(V + dt * c[0], m + dt * c[1], h + dt * c[2], n + dt * c[3],
                            drive, ge, gi)
            new_v = V + sixth * (a[0] + 2 * b[0] + 2 * c[0] + d[0])
            if V < threshold and new_v >= threshold:
                count[i] += 1
            voltage[i] = new_v
            gates[0, i] = min(max(m + sixth * (a[1] + 2 * b[1] + 2 * c[1] + d[1]), 0.0), 1.0)
            gates[1, i] = min(max(h + sixth * (a[2] + 2 * b[2] + 2 * c[2] + d[2]), 0.0), 1.0)
            gates[2, i] = min(max(n + sixth * (a[3] + 2 * b[3] + 2 * c[3] + d[3]), 0.0), 1.0)


def _morris_lecar(voltage, recovery, current, g_e, g_i, e_e, e_i, p, steps, dt, threshold,
                  count):
    """``steps`` sub-steps of every neuron; spikes are added to ``count``."""
    def derivatives(V, w, drive, ge, gi):
        m_inf = 0.5 * (1 + math.tanh((V - p[7]) / p[8]))
        ionic = p[1] * m_inf * (V - p[4]) + p[2] * w * (V - p[5]) + p[3] * (V - p[6])
        dV = 1000 * (drive + (ge * (e_e - V) + gi * (e_i - V)) - ionic) / p[0]
        w_inf = 0.5 * (1 + math.tanh((V - p[9]) / p[10]))
        return dV, math.cosh((V - p[9]) / (2 * p[10])) * (w_inf - w) / p[11]

    half = dt / 2
    sixth = dt / 6
    for i in range(voltage.size):
        drive, ge, gi = current[i], g_e[i], g_i[i]
        for _ in range(steps):
            V, w = np.float64(voltage[i]), np.float64(recovery[i])
            a = derivatives(V, w, drive, ge, gi)
            b = derivatives(V + half * a[0], w + half * a[1], drive, ge, gi)
            c = derivatives(V + half * b[0], w + half * b[1], drive, ge, gi)
            d = derivatives(V + dt * c[0], w + dt * c[1], drive, ge, gi)
            new_v = V + sixth * (a[0] + 2 * b[0] + 2 * c[0] + d[0])
            if V < threshold and new_v >= threshold:
                count[i] += 1
            voltage[i] = new_v
            recovery[i] = min(max(w + sixth * (a[1] + 2 * b[1] + 2 * c[1] + d[1]), 0.0), 1.0)


class Kernels:
    """The loops compiled by numba."""

    def __init__(self, numba):
        jit = numba.njit(cache=True, nogil=True)
        self.hodgkin_huxley = jit(_hodgkin_huxley)
        self.morris_lecar = jit(_morris_lecar)


_kernels: list = []


def kernels() -> Kernels | None:
    """The compiled loops (compiled, or loaded from numba's cache, on their first call);
    None when numba is not installed."""
    if not _kernels:
        try:
            import numba
        except ImportError:          # numba is optional: the NumPy form is used instead
            _kernels.append(None)
        else:
            _kernels.append(Kernels(numba))
    return _kernels[0]
