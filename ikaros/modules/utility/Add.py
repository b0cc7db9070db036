"""Add: element-wise sum of two inputs."""
import numpy as np

from ikaros.module import Input, Output

from ._elementwise import ElementWise


class Add(ElementWise):
    """Outputs the element-wise sum INPUT1 + INPUT2. The inputs must have the same number of
    elements; the output has their shape."""

    INPUT1 = Input("the first term")
    INPUT2 = Input("the second term")
    OUTPUT = Output("the element-wise sum", size_set="INPUT1,INPUT2")

    # many instances run as one NumPy operation (see ikaros/kernel/fusion.py)
    elementwise = ("add", "INPUT1", "INPUT2")
    compiled_op = "add"   # an instruction of the compiled tick (ikaros/kernel/compiled/)

    def tick(self):
        np.add(self._a, self._b, out=self.OUTPUT)
