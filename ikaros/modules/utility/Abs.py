"""Abs: element-wise absolute value."""
import numpy as np

from ikaros.module import Input, Module, Output


class Abs(Module):
    """Outputs the absolute value of every element of the input. The output has the shape of
    the input."""

    INPUT = Input("the signal")
    OUTPUT = Output("the absolute value of each element of INPUT", size_set="INPUT")

    compiled_op = "abs"   # an instruction of the compiled tick (ikaros/kernel/compiled/)

    def tick(self):
        np.abs(self.INPUT, out=self.OUTPUT)
