"""Ones: an array filled with one value."""
from ikaros.module import Module, Output, Parameter


class Ones(Module):
    """Outputs an array in which every element is ``value`` (1 by default). ``size_x`` alone
    gives a 1-D array of that many elements; ``size_x`` and ``size_y`` give a matrix of
    ``size_y`` rows and ``size_x`` columns. The value is written in init and on every tick,
    so a change of ``value`` takes effect at once."""

    size_x = Parameter(1, "number of columns (or of elements, without size_y)", type="int")
    size_y = Parameter(None, "number of rows", type="int")
    value = Parameter(1.0, "the value of every element")
    OUTPUT = Output("the array filled with value", size_param_x="size_x",
                    size_param_y="size_y", size_param="size_x")

    def init(self):
        self.tick()

    def tick(self):
        self.OUTPUT.fill(self.value)
