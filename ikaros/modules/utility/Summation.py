"""Summation: the Ikaros 2 programming example of a module with two inputs."""
import numpy as np

from ikaros.module import Input, Module, Output


class Summation(Module):
    """OUTPUT = INPUT1 + INPUT2, element by element. A programming example
    (docs/writing-modules.md): the inputs must have the same number of elements, which
    ``init`` checks; OUTPUT has the shape of INPUT1. The standard class Add does the same
    (and fuses with its neighbours)."""

    INPUT1 = Input("the first term")
    INPUT2 = Input("the second term, of as many elements as INPUT1")
    OUTPUT = Output("the element-wise sum", shape="INPUT1.shape")

    def init(self):
        if self.INPUT1.size != self.INPUT2.size:
            raise ValueError(f"INPUT1 has {self.INPUT1.size} elements and INPUT2 "
                             f"{self.INPUT2.size}: they must be equal")
        self._second = self.INPUT2.reshape(self.INPUT1.shape)

    def tick(self):
        np.add(self.INPUT1, self._second, out=self.OUTPUT)
