"""The equations of ConductanceNeuronPopulation (MODULES-V3 §12): Hodgkin–Huxley and
Morris–Lecar derivatives, with V in mV and time in seconds."""
import numpy as np


def vtrap(x, s):
    """x / (1 − e^(−x/s)), with its limit s·(1 + x/(2s)) where |x/s| < 1e−6."""
    small = np.abs(x / s) < 1e-6
    safe = np.where(small, 1.0, x)
    return np.where(small, s * (1 + x / (2 * s)), safe / (1 - np.exp(-safe / s)))


def hh_rates(V):
    """(α_m, β_m, α_h, β_h, α_n, β_n) at V."""
    return (0.1 * vtrap(V + 40, 10), 4 * np.exp(-(V + 65) / 18),
            0.07 * np.exp(-(V + 65) / 20), 1 / (1 + np.exp(-(V + 35) / 10)),
            0.01 * vtrap(V + 55, 10), 0.125 * np.exp(-(V + 65) / 80))


def hh_steady_gates(V):
    am, bm, ah, bh, an, bn = hh_rates(V)
    return am / (am + bm), ah / (ah + bh), an / (an + bn)


def hh_derivatives(p, state, current, synaptic):
    """d(V, m, h, n)/dt; ``p`` holds the module's hh_ parameters; ``synaptic`` is a
    function of V giving the synaptic current."""
    V, m, h, n = state
    am, bm, ah, bh, an, bn = hh_rates(V)
    ionic = (p.hh_sodium_conductance * m ** 3 * h * (V - p.hh_sodium_reversal_potential)
             + p.hh_potassium_conductance * n ** 4 * (V - p.hh_potassium_reversal_potential)
             + p.hh_leak_conductance * (V - p.hh_leak_reversal_potential))
    dV = 1000 * (current + synaptic(V) - ionic) / p.hh_capacitance_density
    return (dV, 1000 * (am * (1 - m) - bm * m), 1000 * (ah * (1 - h) - bh * h),
            1000 * (an * (1 - n) - bn * n))


def ml_steady_recovery(p, V):
    return 0.5 * (1 + np.tanh((V - p.ml_recovery_midpoint) / p.ml_recovery_slope))


def ml_derivatives(p, state, current, synaptic):
    """d(V, w)/dt of Morris–Lecar."""
    V, w = state
    m_inf = 0.5 * (1 + np.tanh((V - p.ml_activation_midpoint) / p.ml_activation_slope))
    ionic = (p.ml_calcium_conductance * m_inf * (V - p.ml_calcium_reversal_potential)
             + p.ml_potassium_conductance * w * (V - p.ml_potassium_reversal_potential)
             + p.ml_leak_conductance * (V - p.ml_leak_reversal_potential))
    dV = 1000 * (current + synaptic(V) - ionic) / p.ml_capacitance_density
    dw = np.cosh((V - p.ml_recovery_midpoint) / (2 * p.ml_recovery_slope)) * \
        (ml_steady_recovery(p, V) - w) / p.ml_recovery_time_constant
    return dV, dw


def rk4(derivatives, state, dt):
    """One classical Runge–Kutta step of a tuple of arrays."""
    def shifted(k, f):
        return tuple(s + f * d for s, d in zip(state, k))
    k1 = derivatives(state)
    k2 = derivatives(shifted(k1, dt / 2))
    k3 = derivatives(shifted(k2, dt / 2))
    k4 = derivatives(shifted(k3, dt))
    return tuple(s + dt / 6 * (a + 2 * b + 2 * c + d)
                 for s, a, b, c, d in zip(state, k1, k2, k3, k4))
