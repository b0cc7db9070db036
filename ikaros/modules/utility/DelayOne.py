"""DelayOne: the Ikaros 2 programming example of an output sized in code."""
from ikaros.module import Input, Module, Output


class DelayOne(Module):
    """Outputs its input delayed by one tick: OUTPUT on tick n is INPUT of tick n-1 (on tick
    0, what INPUT held at init: the values of a delay-1 connection). A programming example
    (docs/writing-modules.md): the output's size is set in ``set_sizes`` from the input's,
    and the module keeps the last input in its own array. A connection with ``delay="1"``
    does the same without a module."""

    INPUT = Input("the signal")
    OUTPUT = Output("INPUT of the previous tick")

    def set_sizes(self):
        shape = self.input_shape("INPUT")       # None until the input is sized
        if shape is not None:
            self.set_output_shape("OUTPUT", shape)

    def init(self):
        self._last = self.INPUT.copy()

    def tick(self):
        self.OUTPUT[...] = self._last
        self._last[...] = self.INPUT
