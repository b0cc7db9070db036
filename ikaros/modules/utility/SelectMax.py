"""SelectMax: marks the largest element of the input."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class SelectMax(Module):
    """Outputs an array of the input's shape that is 0 everywhere except at the position of
    the largest input element, where it is 1 (or the input value itself with
    ``keep_value``). When several elements share the maximum, the first one (in row-major
    order) is selected."""

    keep_value = Parameter(False, "output the maximum value at its position instead of 1")
    INPUT = Input("the values to search")
    OUTPUT = Output("one-hot array marking the maximum", size_set="INPUT")

    def tick(self):
        i = int(np.argmax(self.INPUT))
        self.OUTPUT.fill(0)
        self.OUTPUT.flat[i] = self.INPUT.flat[i] if self.keep_value else 1
