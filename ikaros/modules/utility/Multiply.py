"""Multiply: element-wise product of two inputs."""
import numpy as np

from ikaros.module import Input, Output

from ._elementwise import ElementWise


class Multiply(ElementWise):
    """Outputs the element-wise product INPUT1 * INPUT2. The inputs must have the same number
    of elements; the output has their shape."""

    INPUT1 = Input("the first factor")
    INPUT2 = Input("the second factor")
    OUTPUT = Output("the element-wise product", size_set="INPUT1,INPUT2")

    # many instances run as one NumPy operation (see ikaros/kernel/fusion.py)
    elementwise = ("multiply", "INPUT1", "INPUT2")
    compiled_op = "multiply"   # an instruction of the compiled tick (ikaros/kernel/compiled/)

    def tick(self):
        np.multiply(self._a, self._b, out=self.OUTPUT)
