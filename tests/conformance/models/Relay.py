"""Test-only pass-through whose init writes -5."""
import numpy as np

from ikaros.module import Input, Module, Output


class Relay(Module):
    """OUTPUT = INPUT in every tick; init writes -5."""
    INPUT = Input("anything")
    OUTPUT = Output("a copy of the input", size_set="INPUT")

    def init(self):
        self.OUTPUT[...] = -5

    def tick(self):
        np.copyto(self.OUTPUT, self.INPUT)
