"""Divide: element-wise quotient of two inputs."""
import numpy as np

from ikaros.module import Input, Output

from ._elementwise import ElementWise


class Divide(ElementWise):
    """Outputs the element-wise quotient INPUT1 / INPUT2. Where INPUT2 is 0 the output is 0,
    and the first time that happens the module gives a warning. The inputs must have the same
    number of elements; the output has their shape."""

    INPUT1 = Input("the dividend")
    INPUT2 = Input("the divisor")
    OUTPUT = Output("the element-wise quotient; 0 where the divisor is 0",
                    size_set="INPUT1,INPUT2")

    compiled_op = "divide"   # an instruction of the compiled tick (ikaros/kernel/compiled/)

    def init(self):
        super().init()
        self._zero = np.zeros(self.OUTPUT.shape, bool)
        self._nonzero = np.zeros(self.OUTPUT.shape, bool)
        self._warned = False

    def tick(self):
        np.equal(self._b, 0, out=self._zero)
        np.logical_not(self._zero, out=self._nonzero)
        np.divide(self._a, self._b, out=self.OUTPUT, where=self._nonzero)
        if self._zero.any():
            self.OUTPUT[self._zero] = 0
            if not self._warned:
                self._warned = True
                self.warning("division by zero; the output is 0 there")
