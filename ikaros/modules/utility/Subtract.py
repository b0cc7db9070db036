"""Subtract: element-wise difference of two inputs."""
import numpy as np

from ikaros.module import Input, Module, Output


class Subtract(Module):
    """Outputs the element-wise difference INPUT1 - INPUT2. When INPUT2 is not connected the
    output is a copy of INPUT1. Connected inputs must have the same number of elements."""

    INPUT1 = Input("the value subtracted from")
    INPUT2 = Input("the value subtracted; unconnected means 0", optional=True)
    OUTPUT = Output("the element-wise difference", size_set="INPUT1,INPUT2")

    def init(self):
        shape = self.OUTPUT.shape
        self._ok = self.INPUT1.size == self.OUTPUT.size and (
            self.INPUT2 is None or self.INPUT2.size == self.OUTPUT.size)
        if not self._ok:
            other = "" if self.INPUT2 is None else f" and INPUT2 {self.INPUT2.shape}"
            self.fatal_error(f"INPUT1 {self.INPUT1.shape}{other} must have the size of OUTPUT "
                             f"{self.OUTPUT.shape}")
            return
        self._a = self.INPUT1.reshape(shape)
        self._b = None if self.INPUT2 is None else self.INPUT2.reshape(shape)

    def tick(self):
        if not self._ok:
            return
        if self._b is None:
            self.OUTPUT[...] = self._a
        else:
            np.subtract(self._a, self._b, out=self.OUTPUT)
