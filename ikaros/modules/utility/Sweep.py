"""Sweep: a ramp that repeats."""
from ikaros.module import Module, Output, Parameter


class Sweep(Module):
    """Outputs a ramp: ``min`` in init, then one ``step`` more on every tick; a value past
    ``max`` wraps around to ``min``. With min=0, max=1, step=0.5 the output is 0 (init), then
    0.5, 1, 0, 0.5, ... from tick 0. A negative step ramps down from ``max`` instead and wraps
    to ``max`` below ``min``. All elements of the output share the value."""

    outputsize = Parameter(1, "number of elements of a 1-D output", type="int")
    outputsize_x = Parameter(None, "columns of a 2-D output", type="int")
    outputsize_y = Parameter(None, "rows of a 2-D output", type="int")
    min = Parameter(0.0, "the first value of the ramp")
    max = Parameter(1.0, "the last value of the ramp")
    step = Parameter(0.1, "what is added on every tick")
    OUTPUT = Output("the ramp value, in every element",
                    size_param_x="outputsize_x", size_param_y="outputsize_y",
                    size_param="outputsize")

    def init(self):
        self._k = 0          # steps since the ramp last started; value = start + k * step
        self.OUTPUT.fill(self._value())

    def _value(self):
        start = self.max if self.step < 0 else self.min
        return start + self._k * self.step

    def tick(self):
        self._k += 1
        value = self._value()
        tolerance = 1e-6 * abs(self.step)
        if (self.step > 0 and value > self.max + tolerance) or \
                (self.step < 0 and value < self.min - tolerance):
            self._k = 0
            value = self._value()
        self.OUTPUT.fill(value)
