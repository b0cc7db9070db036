"""IntervalDecoder: the value an interval code stands for."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class IntervalDecoder(Module):
    """Decodes an interval code such as IntervalCoder makes: unit i of the n input units is
    centred on min + (i - radius) * step, step = (max - min) / (n - 2 radius - 1), and the
    output is the mean of the centres weighted by the input. For a code that sums to 1 this is
    what Ikaros 2 computed; Ikaros 2 did not divide by the sum, so its result was wrong for
    codes that do not sum to 1 (a value near the ends of the range, a scaled code). When the
    input sums to 0 the output is 0, with a warning the first time. The input must have more
    than 2 radius + 1 elements."""

    radius = Parameter(1, "the radius the code was made with", type="int")
    min = Parameter(0.0, "the value at the centre of unit radius")
    max = Parameter(1.0, "the value at the centre of unit n - 1 - radius")
    INPUT = Input("the interval code")
    OUTPUT = Output("the decoded value", size="1")

    def init(self):
        n = self.INPUT.size
        if n - 2 * self.radius - 1 <= 0:
            self.fatal_error(f"INPUT ({n} elements) must have more than 2 * radius + 1 "
                             f"({2 * self.radius + 1}) elements")
            return
        self._x = self.INPUT.reshape(-1)
        self._units = np.arange(n, dtype=np.float64)
        self._warned = False

    def tick(self):
        r = self.radius
        step = (self.max - self.min) / (self._x.size - 2 * r - 1)
        centres = self.min + (self._units - r) * step
        total = float(np.sum(self._x, dtype=np.float64))
        if total == 0:
            self.OUTPUT[0] = 0
            if not self._warned:
                self._warned = True
                self.warning("the input sums to 0; the output is 0")
            return
        self.OUTPUT[0] = float(np.dot(centres, self._x)) / total
