"""The Ikaros 3 PIDController's tick: filters with rate constants (per second), an
integral and a derivative in seconds, and an output rate limit."""
import math

import numpy as np


def smoothing(rate: float, tick_duration: float) -> np.float32:
    """The weight of the new value in a first-order filter of ``rate`` (1/s) over one tick:
    1 - e^(-rate * dt); a rate of 0 means no filter (weight 1)."""
    if rate <= 0:
        return np.float32(1)
    return np.float32(1.0 - math.exp(-rate * tick_duration))


def smooth(state: np.ndarray, x, weight: np.float32) -> None:
    """state += weight * (x - state), in place."""
    state += weight * (x - state)


class PID3:
    """The per-tick computation of an Ikaros 3 PIDController over the module's arrays."""

    def __init__(self, module):
        self.m = module
        shape = module.OUTPUT.shape
        self.previous = np.zeros(shape, np.float32)     # the last filtered input or error
        self.control = np.zeros(shape, np.float32)

    def clear(self, where) -> None:
        self.previous[where] = 0

    def tick(self, reset: bool) -> None:
        m = self.m
        dt = m.clock.tick_duration
        smooth(m.FILTERED_SETPOINT, m._setpoint, smoothing(m.Fs, dt))
        smooth(m.FILTERED_INPUT, m._input, smoothing(m.Fm, dt))
        np.subtract(m.FILTERED_SETPOINT, m.FILTERED_INPUT, out=m.DELTA)
        if reset:
            for a in (m.OUTPUT, m.FILTERED_ERROR_P, m.FILTERED_ERROR_I, m.FILTERED_ERROR_D,
                      m.INTEGRAL, self.previous):
                a[...] = 0
            return
        smooth(m.FILTERED_ERROR_P, m.DELTA, smoothing(m.Fp, dt))
        smooth(m.FILTERED_ERROR_I, m.DELTA, smoothing(m.Fi, dt))
        if m.derivative_mode == "error":
            signal, sign = m.DELTA, 1.0
        else:                                   # measurement: no kick when the set point moves
            signal, sign = m.FILTERED_INPUT, -1.0   # (input, Ikaros 2's sign, is +1)
        if m.derivative_mode == "input":
            sign = 1.0
        raw = np.float32(sign / dt) * (signal - self.previous)
        self.previous[...] = signal
        smooth(m.FILTERED_ERROR_D, raw, smoothing(m.Fd, dt))
        step = m.FILTERED_ERROR_I * np.float32(dt)
        m.INTEGRAL += step

        c = self.control
        c[...] = m.Kb + m.Kp * m.FILTERED_ERROR_P + m.Ki * m.INTEGRAL + \
            m.Kd * m.FILTERED_ERROR_D
        lo, hi = min(m.Cmin, m.Cmax), max(m.Cmin, m.Cmax)
        clipped = (c > hi) | (c < lo)
        if clipped.any():                       # anti-windup: undo this tick's integration
            np.subtract(m.INTEGRAL, step, out=m.INTEGRAL, where=clipped)
            np.clip(c, lo, hi, out=c)
        limit = m.output_rate_limit * dt
        before = m.OUTPUT.copy() if limit > 0 else None
        smooth(m.OUTPUT, c, smoothing(m.Fc, dt))
        if before is not None:
            np.clip(m.OUTPUT, before - limit, before + limit, out=m.OUTPUT)
