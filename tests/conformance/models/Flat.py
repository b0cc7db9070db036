"""Test-only sink with a flatten="yes" input (Ikaros 3 style)."""
import numpy as np

from ikaros.module import Input, Module, Output


class Flat(Module):
    """Copies its flattened input to OUTPUT."""
    INPUT = Input("connections laid end to end", flatten=True)
    OUTPUT = Output("what INPUT held in the last tick", shape="INPUT.shape")

    def init(self):
        self.OUTPUT[...] = -1

    def tick(self):
        np.copyto(self.OUTPUT, self.INPUT)
