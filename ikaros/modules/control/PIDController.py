"""PIDController: an element-wise PID controller with filtered signals and anti-windup."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class PIDController(Module):
    """Applies PID control to each element of INPUT (the measured value) against the same
    element of SETPOINT (a SETPOINT of one element serves all elements). Every tick the
    set point and the input are smoothed by exponential moving averages, f = F·f + (1−F)·x,
    with constants ``Fs`` and ``Fm`` (0 means no smoothing); their difference is DELTA;
    DELTA is smoothed again separately for the proportional, integral and derivative terms
    (``Fp``, ``Fi``, ``Fd``). The integral adds the I-filtered error once per tick, and the
    derivative is the change of the D-filtered error since the previous tick (0 on the first
    tick). The control value ``Kb + Kp·P + Ki·INTEGRAL + Kd·D`` is clipped to
    ``Cmin``..``Cmax``; while it is clipped the error of that tick is not integrated
    (anti-windup). OUTPUT is the clipped value smoothed with ``Fc``. Gains are per tick,
    not per second. Unlike the Ikaros 2 class, whose derivative term was the change of the
    filtered input with a sign that pushed the output the wrong way and left ``Fd`` unused,
    the derivative here is that of the D-filtered error."""

    Kb = Parameter(0.0, "the bias: a constant added to the control value")
    Kp = Parameter(0.1, "the proportional gain")
    Ki = Parameter(0.0, "the integral gain")
    Kd = Parameter(0.0, "the derivative gain")
    Fs = Parameter(0.0, "set-point filter constant, 0..1 (0: no smoothing)", range=(0, 1))
    Fm = Parameter(0.0, "measurement (INPUT) filter constant, 0..1 (0: no smoothing)",
                   range=(0, 1))
    Fp = Parameter(0.0, "filter constant of the error used by the proportional term, 0..1",
                   range=(0, 1))
    Fi = Parameter(0.0, "filter constant of the error used by the integral term, 0..1",
                   range=(0, 1))
    Fd = Parameter(0.0, "filter constant of the error used by the derivative term, 0..1",
                   range=(0, 1))
    Fc = Parameter(0.0, "filter constant of the control output, 0..1 (0: no smoothing)",
                   range=(0, 1))
    Cmin = Parameter(-1000.0, "the smallest control value; below it the output is clipped "
                     "and integration stops")
    Cmax = Parameter(1000.0, "the largest control value; above it the output is clipped "
                     "and integration stops")

    INPUT = Input("the measured values, one controller per element")
    SETPOINT = Input("the desired values: the size of INPUT, or one element for all")

    OUTPUT = Output("the control output", size_set="INPUT,SETPOINT")
    DELTA = Output("the filtered set point minus the filtered input", size_set="INPUT,SETPOINT")
    FILTERED_SETPOINT = Output("the set point smoothed with Fs", size_set="INPUT,SETPOINT")
    FILTERED_INPUT = Output("the input smoothed with Fm", size_set="INPUT,SETPOINT")
    FILTERED_ERROR_P = Output("DELTA smoothed with Fp: the error of the proportional term",
                              size_set="INPUT,SETPOINT")
    FILTERED_ERROR_I = Output("DELTA smoothed with Fi: the error that is integrated",
                              size_set="INPUT,SETPOINT")
    FILTERED_ERROR_D = Output("DELTA smoothed with Fd: the error whose change is the "
                              "derivative term", size_set="INPUT,SETPOINT")
    INTEGRAL = Output("the integrated error", size_set="INPUT,SETPOINT")

    def init(self):
        shape = self.OUTPUT.shape
        if 1 != self.INPUT.size != self.SETPOINT.size != 1:
            raise ValueError(f"INPUT has {self.INPUT.size} elements and SETPOINT "
                             f"{self.SETPOINT.size}: they must be equal, or one of them 1")
        self._input = self.INPUT.reshape(shape) if self.INPUT.size == self.OUTPUT.size \
            else self.INPUT.reshape(())
        self._setpoint = self.SETPOINT.reshape(shape) if self.SETPOINT.size == \
            self.OUTPUT.size else self.SETPOINT.reshape(())
        self._last_d = np.zeros(shape, dtype=np.float32)
        self._control = np.zeros(shape, dtype=np.float32)
        self._work = np.zeros(shape, dtype=np.float32)
        self._clipped = np.zeros(shape, dtype=bool)
        self._first = True

    @staticmethod
    def _smooth(state, x, f):
        """state = f·state + (1−f)·x, in place."""
        state *= f
        state += (1.0 - f) * x

    def tick(self):
        self._smooth(self.FILTERED_SETPOINT, self._setpoint, self.Fs)
        self._smooth(self.FILTERED_INPUT, self._input, self.Fm)
        np.subtract(self.FILTERED_SETPOINT, self.FILTERED_INPUT, out=self.DELTA)
        self._smooth(self.FILTERED_ERROR_P, self.DELTA, self.Fp)
        self._smooth(self.FILTERED_ERROR_I, self.DELTA, self.Fi)
        self._smooth(self.FILTERED_ERROR_D, self.DELTA, self.Fd)
        if self._first:
            self._last_d[...] = self.FILTERED_ERROR_D
            self._first = False
        self.INTEGRAL += self.FILTERED_ERROR_I

        c = self._control
        np.multiply(self.FILTERED_ERROR_P, self.Kp, out=c)
        c += self.Kb
        np.multiply(self.INTEGRAL, self.Ki, out=self._work)
        c += self._work
        np.subtract(self.FILTERED_ERROR_D, self._last_d, out=self._work)
        self._work *= self.Kd
        c += self._work
        self._last_d[...] = self.FILTERED_ERROR_D

        lo, hi = min(self.Cmin, self.Cmax), max(self.Cmin, self.Cmax)
        np.logical_or(c > hi, c < lo, out=self._clipped)
        if self._clipped.any():                   # anti-windup: undo this tick's integration
            np.subtract(self.INTEGRAL, self.FILTERED_ERROR_I, out=self.INTEGRAL,
                        where=self._clipped)
            np.clip(c, lo, hi, out=c)
        self._smooth(self.OUTPUT, c, self.Fc)
