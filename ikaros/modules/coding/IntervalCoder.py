"""IntervalCoder: an interval (place) code of a value."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class IntervalCoder(Module):
    """Codes the value INPUT[0] in ``outputsize`` units with overlapping receptive fields. The
    units' centres are spaced evenly so that unit ``radius`` is centred on min and unit
    outputsize - 1 - radius on max: centre_i = min + (i - radius) * step with
    step = (max - min) / (outputsize - 2 radius - 1). The units within radius + 1/2 steps of
    the value (2 radius + 1 units for a whole radius) are 1 / (2 radius + 1) and the rest 0,
    so the code sums to 1 inside the range. Only the first input element is coded. outputsize
    must be larger than 2 radius + 1. When max equals min every value codes as min, with a
    warning."""

    outputsize = Parameter(10, "the number of units", type="int")
    radius = Parameter(1.0, "how many units on each side of the nearest one are active")
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
        step = (self.max - self.min) / steps
        if step == 0:
            if not self._warned:
                self._warned = True
                self.warning("max equals min; every value is coded as min")
            p = 0.0
        else:
            p = (float(self._x[0]) - self.min) / step
        distance = np.abs(self._units - p - r)
        self.OUTPUT[...] = np.where(distance < r + 0.5, 1.0 / (1 + 2 * r), 0.0)
