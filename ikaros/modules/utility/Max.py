"""Max: element-wise maximum of two inputs."""
import numpy as np

from ikaros.module import Input, Output

from ._elementwise import ElementWise


class Max(ElementWise):
    """Outputs the element-wise maximum of INPUT1 and INPUT2. The inputs must have the same
    number of elements; the output has their shape."""

    INPUT1 = Input("the first input")
    INPUT2 = Input("the second input")
    OUTPUT = Output("the larger of the two inputs, element by element",
                    size_set="INPUT1,INPUT2")

    compiled_op = "maximum"   # an instruction of the compiled tick (ikaros/kernel/compiled/)

    def tick(self):
        np.maximum(self._a, self._b, out=self.OUTPUT)
