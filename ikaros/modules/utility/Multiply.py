"""Multiply: element-wise product of two inputs."""
import numpy as np

from ikaros.module import Input, Module, Output


class Multiply(Module):
    """Outputs the element-wise product INPUT1 * INPUT2. The inputs must have the same number
    of elements; the output has their shape."""

    INPUT1 = Input("the first factor")
    INPUT2 = Input("the second factor")
    OUTPUT = Output("the element-wise product", size_set="INPUT1,INPUT2")

    def init(self):
        self._ok = self.INPUT1.size == self.INPUT2.size == self.OUTPUT.size
        if not self._ok:
            self.fatal_error(f"INPUT1 {self.INPUT1.shape} and INPUT2 {self.INPUT2.shape} "
                             "must have the same size")
            return
        shape = self.OUTPUT.shape
        self._a = self.INPUT1.reshape(shape)
        self._b = self.INPUT2.reshape(shape)

    def tick(self):
        if self._ok:
            np.multiply(self._a, self._b, out=self.OUTPUT)
