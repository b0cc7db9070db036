"""IntervalCoder: an interval (place) code of a value."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class IntervalCoder(Module):
    """Codes the value INPUT[0] in ``outputsize`` units with overlapping receptive fields, as
    Ikaros 2 does (the class is not in Ikaros 3). The units' centres are spaced evenly so
    that unit ``radius`` is centred on min and unit outputsize - 1 - radius on max:
    centre_i = min + (i - radius) * step with step = (max - min) / (outputsize - 2 radius - 1).
    The value's position a = round((x - min) / step), in whole steps, is computed in single
    precision as in the original (with the defaults 0.5 is a hair below 3.5 steps and rounds
    to 3, as the golden files show); units a .. a + 2 radius are 1 / (2 radius + 1) and the
    rest 0, so the code sums to 1 inside the range, and units that would lie outside the
    output are left out. Only the first input element is coded. outputsize must be larger
    than 2 radius + 1. When max equals min every value codes as min, with a warning."""

    outputsize = Parameter(10, "the number of units", type="int")
    radius = Parameter(1.0, "how many units on each side of the value's unit are active")
    min = Parameter(0.0, "the value at the centre of unit radius")
    max = Parameter(1.0, "the value at the centre of unit outputsize - 1 - radius")
    INPUT = Input("the value to code (its first element)")
    OUTPUT = Output("the interval code", size_param="outputsize")

    def init(self):
        n = self.OUTPUT.size
        if n - 2 * self.radius - 1 <= 0:
            self.fatal_error(f"outputsize ({n}) must be larger than 2 * radius + 1 "
                             f"({2 * self.radius + 1:g})")
            return
        self._x = self.INPUT.reshape(-1)
        self._units = np.arange(n, dtype=np.float64)
        self._warned = False

    def tick(self):
        r = self.radius
        steps = self.OUTPUT.size - 2 * r - 1
        step = np.float32((self.max - self.min) / steps)
        if step == 0:
            if not self._warned:
                self._warned = True
                self.warning("max equals min; every value is coded as min")
            a = 0.0
        else:
            a = float(np.floor((self._x[0] - np.float32(self.min)) / step + np.float32(0.5)))
        inside = (self._units >= a) & (self._units <= a + 2 * r)
        self.OUTPUT[...] = np.where(inside, 1.0 / (1 + 2 * r), 0.0)
