"""Test-only sink: OUTPUT is a copy of what INPUT held while the module ticked."""
import numpy as np

from ikaros.module import Input, Module, Output


class Sink(Module):
    """Copies its input to its output in tick (init writes -1 everywhere)."""
    INPUT = Input("anything")
    OUTPUT = Output("what INPUT held during the last tick", shape="INPUT.shape")

    def init(self):
        self.OUTPUT[...] = -1

    def tick(self):
        np.copyto(self.OUTPUT, self.INPUT)
