"""SpectralTiming: a spectral timing code of stimulus traces."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class SpectralTiming(Module):
    """A version of the spectral timing model (Grossberg & Schmajuk, 1989). Each input element
    drives a stimulus trace that decays by the factor ``decay`` on every tick and is raised to
    the input whenever the input is larger: TRACE <- max(decay * TRACE, INPUT). The trace
    feeds ``no_of_taps`` temporal units, each tuned to a different trace level: unit j
    (j = 0 .. no_of_taps - 1) of input element i outputs
    y_i exp(-(y_i - (j + 1) / no_of_taps)^2 / (2 sigma^2)), y_i being the trace. As the trace
    decays after a stimulus, the units peak one after another, from the last row to the
    first. With sigma 0 the output is 0. OUTPUT has one row per tap and, as in Ikaros 2 (the
    class is not in Ikaros 3), a column for each element of INPUT's first row only: of a
    matrix input only the first row is coded, and the other rows of TRACE stay 0 (the golden
    files show it, and the formula above on their cases)."""

    no_of_taps = Parameter(10, "the number of temporal units for each input element",
                           type="int")
    sigma = Parameter(0.05, "the width of each unit's tuning to the trace level")
    decay = Parameter(0.985, "the factor the trace is multiplied by on every tick")
    INPUT = Input("the stimuli")
    OUTPUT = Output("the temporal units: one row per tap, one column per element of INPUT's "
                    "first row", shape="@no_of_taps, INPUT.cols")
    TRACE = Output("the decaying stimulus trace of each input element", size_set="INPUT")

    def init(self):
        n = self.OUTPUT.shape[1]
        self._x = self.INPUT.reshape(-1)[:n]
        self._trace = self.TRACE.reshape(-1)[:n]
        taps = self.OUTPUT.shape[0]
        self._levels = (np.arange(1, taps + 1, dtype=np.float32) / taps)[:, None]

    def tick(self):
        trace = self._trace
        trace *= np.float32(self.decay)
        np.maximum(trace, self._x, out=trace)
        if self.sigma == 0:
            self.OUTPUT.fill(0)
            return
        y = trace[None, :]
        self.OUTPUT[...] = y * np.exp(-(y - self._levels) ** 2 / (2 * self.sigma ** 2))
