"""Subtract: element-wise difference of two inputs."""
import numpy as np

from ikaros.module import Input, Output

from ._elementwise import ElementWise


class Subtract(ElementWise):
    """Outputs the element-wise difference INPUT1 - INPUT2. When INPUT2 is not connected the
    output is a copy of INPUT1. Connected inputs must have the same number of elements."""

    INPUT1 = Input("the value subtracted from")
    INPUT2 = Input("the value subtracted; unconnected means 0", optional=True)
    OUTPUT = Output("the element-wise difference", size_set="INPUT1,INPUT2")

    # many instances run as one NumPy operation (see ikaros/kernel/fusion.py)
    elementwise = ("subtract", "INPUT1", "INPUT2")
    compiled_op = "subtract"   # an instruction of the compiled tick (ikaros/kernel/compiled/)

    def tick(self):
        if self._b is None:
            self.OUTPUT[...] = self._a
        else:
            np.subtract(self._a, self._b, out=self.OUTPUT)
