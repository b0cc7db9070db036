"""IntervalDecoder: the value an interval code stands for."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class IntervalDecoder(Module):
    """Decodes an interval code such as IntervalCoder makes, as Ikaros 2 does (the class is
    not in Ikaros 3): with step = (max - min) / (n - 2 radius - 1) for n input units, the
    output is min + step * (sum_i i x_i - radius), the centre of the code's weighted
    position. Ikaros 2 does not divide the weighted position by the sum of the input (the
    golden files show it), a defect: the result is right only for a code that sums to 1 (not
    near the ends of the range, not a scaled code), and an all-zero input gives
    min - radius * step. ``normalize="yes"`` (this project's) divides by the sum, giving the
    mean of the unit centres weighted by the input; an input that sums to 0 then gives 0,
    with a warning the first time. The input must have more than 2 radius + 1 elements."""

    radius = Parameter(1, "the radius the code was made with", type="int")
    min = Parameter(0.0, "the value at the centre of unit radius")
    max = Parameter(1.0, "the value at the centre of unit n - 1 - radius")
    normalize = Parameter(False, "no: the weighted position is not divided by the input's "
                          "sum (Ikaros 2); yes: the weighted mean of the unit centres")
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
        position = float(np.dot(self._units, self._x))
        if self.normalize:
            total = float(np.sum(self._x, dtype=np.float64))
            if total == 0:
                self.OUTPUT[0] = 0
                if not self._warned:
                    self._warned = True
                    self.warning("the input sums to 0; the output is 0")
                return
            position /= total
        self.OUTPUT[0] = self.min + step * (position - r)
