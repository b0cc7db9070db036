"""Tanh: the hyperbolic tangent of each element."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Tanh(Module):
    """Outputs the hyperbolic tangent of each element of INPUT; the output has the input's
    shape. With ``debug`` the output is printed on every tick."""

    debug = Parameter(False, "print the output on every tick")
    INPUT = Input("the values")
    OUTPUT = Output("tanh of each input element", size_set="INPUT")

    compiled_op = "tanh"   # an instruction of the compiled tick (ikaros/kernel/compiled/)

    def tick(self):
        np.tanh(self.INPUT, out=self.OUTPUT)
        if self.debug:
            self.print(np.array2string(self.OUTPUT, precision=4))
