"""Min: element-wise minimum of two inputs."""
import numpy as np

from ikaros.module import Input, Output

from ._elementwise import ElementWise


class Min(ElementWise):
    """Outputs the element-wise minimum of INPUT1 and INPUT2. The inputs must have the same
    number of elements; the output has their shape."""

    INPUT1 = Input("the first input")
    INPUT2 = Input("the second input")
    OUTPUT = Output("the smaller of the two inputs, element by element",
                    size_set="INPUT1,INPUT2")

    compiled_op = "minimum"   # an instruction of the compiled tick (ikaros/kernel/compiled/)

    def tick(self):
        np.minimum(self._a, self._b, out=self.OUTPUT)
