"""PopulationCoder: a Gaussian population code of each input value."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class PopulationCoder(Module):
    """Codes each element of INPUT as a row of ``size`` units with Gaussian tuning curves, as
    Ikaros 2 does (the class is not in Ikaros 3). Unit k of a row prefers the value
    min + k (max - min) / (size - 1); its activity is exp(-(k - c)^2 / (2 sigma^2)), where
    c = (size - 1) (x - min) / (max - min) is the value's position in units and sigma the
    tuning width in units. Each row is then divided by its sum, so that it sums to 1 (a row
    whose units are all 0 in single precision, for a value far outside min..max, stays 0),
    and multiplied by AMPLITUDE when that is connected: one element scales all rows,
    otherwise element j scales row j. The output has one row per input element.

    Ikaros 2 reads sigma as a whole number (cut towards 0), a defect: a sigma of 0.5 is 0,
    and then every row is 0 (the golden files show it). ``whole_sigma="no"`` uses sigma as
    given; ``normalize="no"`` leaves each curve's peak at 1 (this project's other form). With
    a sigma of 0 a value that falls exactly on a unit gives 1 there (this project's reading:
    no reference shows that case). When max equals min every value codes as min, with a
    warning."""

    size = Parameter(10, "the number of units coding each value", type="int")
    sigma = Parameter(1.0, "the width (standard deviation) of the tuning curves, in units")
    min = Parameter(0.0, "the value preferred by the first unit")
    max = Parameter(1.0, "the value preferred by the last unit")
    normalize = Parameter(True, "yes: each row sums to 1 (Ikaros 2); no: each curve peaks at 1")
    whole_sigma = Parameter(True, "yes: sigma is cut to a whole number, as Ikaros 2 does (0.5 "
                            "gives 0: all rows 0); no: sigma is used as given")
    INPUT = Input("the values to code")
    AMPLITUDE = Input("the height of each row's code: one element for all rows, or one per "
                      "input element", optional=True)
    OUTPUT = Output("the population code, one row per input element", shape="INPUT.size, @size")

    def init(self):
        self._x = self.INPUT.reshape(-1, 1)
        self._code = self.OUTPUT.reshape(self._x.shape[0], -1)
        self._units = np.arange(self._code.shape[1], dtype=np.float32)[None, :]
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
        span = np.float32(self.max - self.min)
        if span == 0:
            if not self._warned:
                self._warned = True
                self.warning("max equals min; every value is coded as min")
            c = np.zeros(self._x.shape, np.float32)
        else:
            c = np.float32(self._units.size - 1) * (self._x - np.float32(self.min)) / span
        sigma = float(int(self.sigma)) if self.whole_sigma else float(self.sigma)
        d = self._units - c
        if sigma > 0:
            code = np.exp(-d * d / np.float32(2 * sigma * sigma))
        else:
            code = (d == 0).astype(np.float32)
        if self.normalize:
            total = code.sum(axis=1, keepdims=True)
            np.divide(code, total, out=code, where=total > 0)
        if self._amplitude is not None:
            code *= self._amplitude
        self._code[...] = code
