"""Mean: the mean of all elements of the input."""
import numpy as np

from ikaros.module import Input, Module, Output


class Mean(Module):
    """Outputs the mean of all elements of INPUT (of any shape) as a single element."""

    INPUT = Input("the values to average")
    OUTPUT = Output("the mean of all input elements", size="1")

    def tick(self):
        self.OUTPUT[0] = np.mean(self.INPUT, dtype=np.float64)
