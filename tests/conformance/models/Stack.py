"""Test-only sink with a stack="yes" input (Ikaros 3 style)."""
import numpy as np

from ikaros.module import Input, Module, Output


class Stack(Module):
    """Copies its stacked input to OUTPUT."""
    INPUT = Input("one slice per connection", stack=True)
    OUTPUT = Output("what INPUT held in the last tick", shape="INPUT.shape")

    def init(self):
        self.OUTPUT[...] = -1

    def tick(self):
        np.copyto(self.OUTPUT, self.INPUT)
