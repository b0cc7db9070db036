"""Sum: the sum of all elements of the input."""
import numpy as np

from ikaros.module import Input, Module, Output


class Sum(Module):
    """Outputs the sum of all elements of INPUT (of any shape) as a single element."""

    INPUT = Input("the values to add up")
    OUTPUT = Output("the sum of all input elements", size="1")

    compiled_op = "sum"   # an instruction of the compiled tick (ikaros/kernel/compiled/)

    def tick(self):
        self.OUTPUT[0] = np.sum(self.INPUT, dtype=np.float64)
