"""Test-only pass-through whose init copies its input (for the time-zero rules)."""
import numpy as np

from ikaros.module import Input, Module, Output


class Pass(Module):
    """OUTPUT = INPUT, in init and in every tick."""
    INPUT = Input("anything")
    OUTPUT = Output("a copy of the input", size_set="INPUT")

    def init(self):
        np.copyto(self.OUTPUT, self.INPUT)

    def tick(self):
        np.copyto(self.OUTPUT, self.INPUT)
