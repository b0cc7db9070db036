"""Average: the average of a signal over time."""
import numpy as np

from ikaros.module import TERMINATE, Input, Module, Output, Parameter


class Average(Module):
    """Averages each element of the input over time. CMA (cumulative moving average) is the
    mean of every input since the start; SMA (simple moving average) the mean of the last
    ``window_size`` inputs (of those received so far, while fewer have arrived; changing
    window_size restarts the window); EMA (exponential moving average) moves the output a
    fraction ``alpha`` towards the input on every tick, starting from 0. ``operation`` applies
    abs or a square to the input first, and ``sqrt`` takes the square root of the absolute
    average, so operation=sqr with sqrt=yes gives a root mean square. When the absolute value
    of output element ``select`` falls below ``termination_criterion`` the module stops the
    run (the default 0 never does). Ikaros 3 changed the class: in a file of dialect 3 it
    outputs one value, the mean of all elements of the input at this tick (summed in
    float32; 0 for an empty input), and the parameters are not used."""

    type = Parameter("CMA", "the kind of average", options="CMA/SMA/EMA")
    operation = Parameter("none", "what is applied to the input before averaging",
                          options="none/abs/sqr")
    sqrt = Parameter(False, "output the square root of the absolute average")
    window_size = Parameter(100, "the number of ticks averaged by SMA", type="int")
    alpha = Parameter(0.1, "the weight of the new input for EMA", range=(0, 1))
    termination_criterion = Parameter(0.0, "stop the run when the absolute average at select "
                                      "falls below this value")
    select = Parameter(0, "the output element checked against termination_criterion",
                       type="int")
    INPUT = Input("the signal to average")
    OUTPUT = Output("the average over time (Ikaros 3: the mean of all input elements, one "
                    "value)", size_set="INPUT")

    def configure(self):
        if self.dialect == "3":
            self.set_output_shape("OUTPUT", 1)

    def init(self):
        if self.dialect == "3":
            return
        if not 0 <= self.select < max(1, self.OUTPUT.size):
            self.fatal_error(f"select ({self.select}) is outside the output, which has "
                             f"{self.OUTPUT.size} elements")
            return
        shape = self.OUTPUT.shape
        self._x = np.zeros(shape, np.float64)
        self._sum = np.zeros(shape, np.float64)
        self._count = 0
        self._ema = np.zeros(shape, np.float64)
        self._window = None
        self._window_length = None
        self._done = False
        self.OUTPUT.fill(0)

    def _sma(self):
        length = max(1, self.window_size)
        if length != self._window_length:
            self._window_length = length
            self._window = np.zeros((length,) + self._x.shape, np.float64)
            self._wsum = np.zeros(self._x.shape, np.float64)
            self._wpos = 0
            self._wcount = 0
        slot = self._window[self._wpos]
        self._wsum -= slot
        slot[...] = self._x
        self._wsum += slot
        self._wpos = (self._wpos + 1) % length
        self._wcount = min(self._wcount + 1, length)
        if self._wpos == 0:                     # re-add now and then to stop drift
            np.sum(self._window[:self._wcount], axis=0, out=self._wsum)
        return self._wsum / self._wcount

    def tick(self):
        if self.dialect == "3":
            n = self.INPUT.size
            self.OUTPUT[0] = np.sum(self.INPUT, dtype=np.float32) / np.float32(n) if n else 0
            return
        x = self._x
        if self.operation == "abs":
            np.abs(self.INPUT, out=x)
        elif self.operation == "sqr":
            np.square(self.INPUT, out=x, dtype=np.float64)
        else:
            x[...] = self.INPUT
        if self.type == "SMA":
            avg = self._sma()
        elif self.type == "EMA":
            self._ema *= 1.0 - self.alpha
            self._ema += self.alpha * x
            avg = self._ema
        else:
            self._sum += x
            self._count += 1
            avg = self._sum / self._count
        if self.sqrt:
            avg = np.sqrt(np.abs(avg))
        self.OUTPUT[...] = avg
        if not self._done and self.OUTPUT.size and \
                abs(float(self.OUTPUT.flat[self.select])) < self.termination_criterion:
            self._done = True
            self.notify(TERMINATE, f"the average at {self.select} fell below "
                        f"{self.termination_criterion:g}")
