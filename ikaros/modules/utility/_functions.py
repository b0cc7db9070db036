"""A base for the Ikaros 3 element-wise functions of one input (Exp, Square, Negate, ...)."""
import numpy as np

from ikaros.module import Input, Module, Output


class ElementFunction(Module):
    """Applies ``function`` (a NumPy ufunc, or a function of (x, out)) to every element of
    INPUT; the output has the shape of the input. Overflow and division by zero give the
    IEEE results (inf) without a warning, as in the original's float arithmetic."""

    INPUT = Input("the signal")
    OUTPUT = Output("the function of each element of INPUT", size_set="INPUT")

    function = None

    def tick(self):
        with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
            type(self).function(self.INPUT, out=self.OUTPUT)
