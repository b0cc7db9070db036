"""Delay: a legacy delay line."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Delay(Module):
    """Delays a signal. As in Ikaros 2, ``delay`` counts the default delay-1 connection into
    the module: the module itself holds its input for ``delay - 1`` ticks, so a source
    connected with the default delay reaches OUTPUT ``delay`` ticks later. With ``delay`` 1
    (or less) the input is copied straight through. Until the line has filled the output is
    0. Connection delays (``delay="3"``) do the same job and are preferred in new models."""

    delay = Parameter(1, "the delay in ticks, including the default delay-1 connection",
                      type="int")
    INPUT = Input("the signal to delay")
    OUTPUT = Output("the delayed signal", size_set="INPUT")

    def init(self):
        self._length = max(0, self.delay - 1)
        self._line = np.zeros((self._length,) + self.OUTPUT.shape, np.float32)
        self._next = 0

    def tick(self):
        if self._length == 0:
            self.OUTPUT[...] = self.INPUT
            return
        slot = self._line[self._next]
        self.OUTPUT[...] = slot
        slot[...] = self.INPUT
        self._next = (self._next + 1) % self._length
