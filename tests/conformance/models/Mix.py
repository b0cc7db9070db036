"""Test-only adder: OUTPUT = INPUT1 + INPUT2 (INPUT2 optional), shaped like INPUT1."""
import numpy as np

from ikaros.module import Input, Module, Output


class Mix(Module):
    """Adds two inputs; the output takes the shape of INPUT1."""
    INPUT1 = Input("first term")
    INPUT2 = Input("second term", optional=True)
    OUTPUT = Output("the sum", shape="INPUT1.shape")

    def init(self):
        self.OUTPUT[...] = 0

    def tick(self):
        if self.INPUT2 is None:
            np.copyto(self.OUTPUT, self.INPUT1)
        else:
            np.add(self.INPUT1, self.INPUT2.reshape(self.INPUT1.shape), out=self.OUTPUT)
