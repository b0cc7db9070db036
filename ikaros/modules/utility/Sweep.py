"""Sweep: a ramp that repeats."""
import numpy as np

from ikaros.module import Module, Output, Parameter


class Sweep(Module):
    """Outputs a ramp, as Ikaros 2 does (golden files): ``min`` in init, then on every tick
    ``step`` is added first, and a value above ``max`` becomes ``min``, one below ``min``
    becomes ``max``. With min=0, max=1, step=0.5 the output is 0 (init), then 0.5, 1, 0,
    0.5, ... from tick 0; with step=-0.3 it is 0 (init), then 1, 0.7, 0.4, 0.1, 1, ... The
    value is added up in single precision, as in the original, so a step that float32
    cannot hold exactly drifts: ten steps of 0.1 give 1.0000001, which is past 1, so with
    min=0, max=1, step=0.1 the ramp wraps to 0 where 1 would be due. All elements of the
    output share the value."""

    outputsize = Parameter(1, "number of elements of a 1-D output", type="int")
    outputsize_x = Parameter(None, "columns of a 2-D output", type="int")
    outputsize_y = Parameter(None, "rows of a 2-D output", type="int")
    min = Parameter(0.0, "the first value of the ramp, and where it wraps to past max")
    max = Parameter(1.0, "the last value of the ramp, and where it wraps to below min")
    step = Parameter(0.1, "what is added on every tick")
    OUTPUT = Output("the ramp value, in every element",
                    size_param_x="outputsize_x", size_param_y="outputsize_y",
                    size_param="outputsize")

    def init(self):
        self._value = np.float32(self.min)
        self.OUTPUT.fill(self._value)

    def tick(self):
        value = np.float32(self._value + np.float32(self.step))
        if value > np.float32(self.max):
            value = np.float32(self.min)
        elif value < np.float32(self.min):
            value = np.float32(self.max)
        self._value = value
        self.OUTPUT.fill(value)
