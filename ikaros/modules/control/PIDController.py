"""PIDController: an element-wise PID controller with filtered signals and anti-windup."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._pid3 import PID3


class PIDController(Module):
    """Applies PID control to each element of INPUT (the measured value) against the same
    element of SETPOINT (a SETPOINT of one element serves all elements). Every tick the
    set point and the input are smoothed by exponential moving averages, f = F·f + (1−F)·x,
    with constants ``Fs`` and ``Fm`` (0 means no smoothing); their difference is DELTA;
    DELTA is smoothed again separately for the proportional, integral and derivative terms
    (``Fp``, ``Fi``, ``Fd``). The integral adds the I-filtered error once per tick. The
    control value ``Kb + Kp·P + Ki·INTEGRAL + Kd·D`` is clipped to ``Cmin``..``Cmax``;
    while it is clipped the error of that tick is not integrated (anti-windup). OUTPUT is
    the clipped value smoothed with ``Fc``. Gains are per tick, not per second. The
    derivative term D is chosen by ``derivative_mode``: ``input`` (the default in an Ikaros
    2 file, as the Ikaros 2 class computes it) is the change of the filtered input since the
    previous tick, a sign that pushes the output the wrong way, with ``Fd`` unused;
    ``measurement`` is minus that change (the corrected sign; Ikaros 3's default);
    ``error`` (this project's) is the change of the D-filtered error. As in Ikaros 2 the
    previous value starts at 0, so on the first tick the change is the signal itself (the
    golden files show it).

    Ikaros 2 ignores RESET (the code that would use it is switched off there), so its
    integral keeps adding up while RESET is above 0; an Ikaros 2 file gets that by default.
    ``use_reset="yes"`` makes RESET work: on a tick when its first element is above 0, every
    controller starts afresh (filters, integral and derivative memory at 0) before that tick
    is computed. Two more optional inputs are this project's (neither Ikaros 2 nor Ikaros 3
    has them), each of one element, for all controllers, or of the size of INPUT; left
    unconnected, the controller works as above. INPUT_VALID: an element whose value is 0 or
    below is held for the tick (all its outputs and its integral keep their values), for a
    measurement that is missing. GATED: an element whose value is 0 or below is switched
    off: its OUTPUT and every signal and memory of it are 0, so it starts afresh when the
    gate opens again.

    In an Ikaros 3 file (dialect 3) the class computes as Ikaros 3 does: the filter
    constants ``Fs`` ... ``Fc`` are rates (1/s; 0 is no filter): each filter moves the
    fraction 1 − e^(−F·tick_duration) of the way to its input per tick. The integral adds
    the I-filtered error times tick_duration. The derivative (FILTERED_ERROR_D, filtered
    with ``Fd``) is per second: with ``derivative_mode="measurement"`` (the default) minus
    the change of the filtered input, with ``"error"`` the change of DELTA, from 0 before
    the first tick. The clipped control value is smoothed with ``Fc`` and then changes by at
    most ``output_rate_limit`` per second (0: no limit). RESET (used by default there)
    computes the filtered set point, input and DELTA but sets OUTPUT, the error filters, the
    integral and the derivative memory to 0 for that tick. ``output_rate_limit`` is used
    only in dialect 3."""
    state = ("_last_d",)     # the derivative's memory (saved with the outputs)

    Kb = Parameter(0.0, "the bias: a constant added to the control value")
    Kp = Parameter(0.1, "the proportional gain")
    Ki = Parameter(0.0, "the integral gain")
    Kd = Parameter(0.0, "the derivative gain")
    Fs = Parameter(0.0, "set-point filter constant, 0..1 (0: no smoothing; Ikaros 3: a rate "
                   "in 1/s)", range=(0, None))
    Fm = Parameter(0.0, "measurement (INPUT) filter constant, 0..1 (0: no smoothing; "
                   "Ikaros 3: a rate)", range=(0, None))
    Fp = Parameter(0.0, "filter constant of the error used by the proportional term, 0..1 "
                   "(Ikaros 3: a rate)", range=(0, None))
    Fi = Parameter(0.0, "filter constant of the error used by the integral term, 0..1 "
                   "(Ikaros 3: a rate)", range=(0, None))
    Fd = Parameter(0.0, "filter constant of the error used by the derivative term, 0..1 "
                   "(Ikaros 3: a rate)", range=(0, None))
    Fc = Parameter(0.0, "filter constant of the control output, 0..1 (0: no smoothing; "
                   "Ikaros 3: a rate)", range=(0, None))
    output_rate_limit = Parameter(0.0, "Ikaros 3: the largest change of OUTPUT per second "
                                  "(0: no limit)", range=(0, None))
    derivative_mode = Parameter("input", "what the derivative term differentiates: the "
                                "filtered input (input, Ikaros 2), minus it (measurement, "
                                "Ikaros 3) or the error (error: the D-filtered error; in an "
                                "Ikaros 3 file DELTA)", options="input/measurement/error",
                                default_v3="measurement")
    use_reset = Parameter(False, "whether RESET is used: no in an Ikaros 2 file (Ikaros 2 "
                          "ignores it), yes in an Ikaros 3 file", default_v3=True)
    Cmin = Parameter(-1000.0, "the smallest control value; below it the output is clipped "
                     "and integration stops")
    Cmax = Parameter(1000.0, "the largest control value; above it the output is clipped "
                     "and integration stops")

    INPUT = Input("the measured values, one controller per element")
    SETPOINT = Input("the desired values: the size of INPUT, or one element for all")
    GATED = Input("this project's: where 0 or below, the controller is off (output 0, state "
                  "cleared)", optional=True)
    INPUT_VALID = Input("this project's: where 0 or below, the measurement is missing and the "
                        "controller holds", optional=True)
    RESET = Input("a first element above 0 clears every controller's state; used only with "
                  "use_reset", optional=True)

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
        if self.dialect != "3":
            above = [n for n in ("Fs", "Fm", "Fp", "Fi", "Fd", "Fc") if getattr(self, n) > 1]
            if above:
                raise ValueError(f"the filter constants {', '.join(above)} must be at most 1 "
                                 f"(in an Ikaros 3 file they are rates)")
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
        self._gate = self._mask("GATED")
        self._valid = self._mask("INPUT_VALID")
        self._state = (self.OUTPUT, self.DELTA, self.FILTERED_SETPOINT, self.FILTERED_INPUT,
                       self.FILTERED_ERROR_P, self.FILTERED_ERROR_I, self.FILTERED_ERROR_D,
                       self.INTEGRAL, self._last_d)
        self._pid3 = PID3(self) if self.dialect == "3" else None

    def _mask(self, name):
        """A function giving the elements where the input ``name`` is above 0 (None when
        the input is not connected)."""
        x = getattr(self, name)
        if x is None:
            return None
        if x.size not in (1, self.OUTPUT.size):
            raise ValueError(f"{name} has {x.size} elements: it must have 1 or as many as "
                             f"INPUT ({self.OUTPUT.size})")
        shape = self.OUTPUT.shape
        return lambda: np.broadcast_to(x.reshape(shape if x.size > 1 else ()) > 0, shape)

    @staticmethod
    def _smooth(state, x, f):
        """state = f·state + (1−f)·x, in place."""
        state *= f
        state += (1.0 - f) * x

    def _clear(self, where):
        for a in self._state:
            a[where] = 0
        if self._pid3 is not None:
            self._pid3.clear(where)

    def tick(self):
        reset = self.use_reset and self.RESET is not None and self.RESET.size and \
            self.RESET.flat[0] > 0
        if reset and self._pid3 is None:
            self._clear(Ellipsis)
        held = None
        if self._valid is not None:
            held = ~self._valid()
            kept = [a[held] for a in self._state] if held.any() else None
        if self._pid3 is not None:
            self._pid3.tick(bool(reset))
        else:
            self._compute()
        if held is not None and kept is not None:
            for a, k in zip(self._state, kept):
                a[held] = k
        if self._gate is not None:
            self._clear(~self._gate())

    def _compute(self):
        self._smooth(self.FILTERED_SETPOINT, self._setpoint, self.Fs)
        self._smooth(self.FILTERED_INPUT, self._input, self.Fm)
        np.subtract(self.FILTERED_SETPOINT, self.FILTERED_INPUT, out=self.DELTA)
        self._smooth(self.FILTERED_ERROR_P, self.DELTA, self.Fp)
        self._smooth(self.FILTERED_ERROR_I, self.DELTA, self.Fi)
        self._smooth(self.FILTERED_ERROR_D, self.DELTA, self.Fd)
        mode = self.derivative_mode
        signal = self.FILTERED_ERROR_D if mode == "error" else self.FILTERED_INPUT
        self.INTEGRAL += self.FILTERED_ERROR_I

        c = self._control
        np.multiply(self.FILTERED_ERROR_P, self.Kp, out=c)
        c += self.Kb
        np.multiply(self.INTEGRAL, self.Ki, out=self._work)
        c += self._work
        np.subtract(signal, self._last_d, out=self._work)
        self._work *= -self.Kd if mode == "measurement" else self.Kd
        c += self._work
        self._last_d[...] = signal

        lo, hi = min(self.Cmin, self.Cmax), max(self.Cmin, self.Cmax)
        np.logical_or(c > hi, c < lo, out=self._clipped)
        if self._clipped.any():                   # anti-windup: undo this tick's integration
            np.subtract(self.INTEGRAL, self.FILTERED_ERROR_I, out=self.INTEGRAL,
                        where=self._clipped)
            np.clip(c, lo, hi, out=c)
        self._smooth(self.OUTPUT, c, self.Fc)
