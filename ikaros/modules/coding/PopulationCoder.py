"""PopulationCoder: a Gaussian population code of each input value."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class PopulationCoder(Module):
    """Codes each element of INPUT as a row of ``size`` units with Gaussian tuning curves.
    Unit k of a row prefers the value min + k (max - min) / (size - 1), and its activity is
    exp(-(k - c)^2 / (2 sigma^2)), where c = (size - 1) (x - min) / (max - min) is the value's
    position in units and sigma the tuning width in units. The output has one row per input
    element. When AMPLITUDE is connected the rows are multiplied by it: one element scales all
    rows, otherwise element j scales row j. (Ikaros 2 ignored AMPLITUDE and rounded sigma down
    to a whole number.) A sigma of 0 makes the nearest unit 1. When max equals min every value
    codes as min, with a warning."""

    size = Parameter(10, "the number of units coding each value", type="int")
    sigma = Parameter(1.0, "the width (standard deviation) of the tuning curves, in units")
    min = Parameter(0.0, "the value preferred by the first unit")
    max = Parameter(1.0, "the value preferred by the last unit")
    INPUT = Input("the values to code")
    AMPLITUDE = Input("the height of each row's code: one element for all rows, or one per "
                      "input element", optional=True)
    OUTPUT = Output("the population code, one row per input element", shape="INPUT.size, @size")

    def init(self):
        self._x = self.INPUT.reshape(-1, 1)
        self._units = np.arange(self.OUTPUT.shape[1], dtype=np.float64)[None, :]
        self._amplitude = None
        if self.AMPLITUDE is not None:
            a = self.AMPLITUDE.reshape(-1)
            if a.size == 1:
                self._amplitude = a
            elif a.size == self._x.shape[0]:
                self._amplitude = a.reshape(-1, 1)
            else:
                self.fatal_error(f"AMPLITUDE has {a.size} elements; it must have 1 or as many "
                                 f"as INPUT ({self._x.shape[0]})")
                return
        self._warned = False

    def tick(self):
        span = self.max - self.min
        if span == 0:
            if not self._warned:
                self._warned = True
                self.warning("max equals min; every value is coded as min")
            c = np.zeros(self._x.shape)
        else:
            c = (self._units.size - 1) * (self._x.astype(np.float64) - self.min) / span
        if self.sigma > 0:
            code = np.exp(-(self._units - c) ** 2 / (2 * self.sigma ** 2))
        else:
            code = (self._units == np.floor(c + 0.5)).astype(np.float64)
        if self._amplitude is not None:
            code *= self._amplitude
        self.OUTPUT[...] = code
