"""DataBuffer: a matrix of past inputs."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class DataBuffer(Module):
    """Keeps ``size`` past inputs as the rows of a matrix (the input is read as one flat
    vector). On every tick the current input replaces a row chosen by ``update_policy``:
    random replaces a random row; circular writes rows 0, 1, 2, ... in turn and starts over at
    0; queue puts the newest input in row 0 and moves the older ones one row down, dropping
    the oldest. Rows that have not been written are 0. (The original used the random policy
    whatever update_policy said.)"""

    size = Parameter(10, "the number of inputs kept (rows of the output)", type="int")
    update_policy = Parameter("random", "which row the new input replaces",
                              options="random/circular/queue")
    seed = Parameter(None, "seed for the random policy; unset (or 0) gives a different run "
                     "every time", type="int")
    debug = Parameter(False, "print the buffer on every tick")
    INPUT = Input("the vector to store")
    OUTPUT = Output("the buffer: one stored input per row")

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape is None:
            return
        if self.size < 1:
            raise ValueError(f"size must be at least 1, not {self.size}")
        n = math.prod(shape)
        self.set_output_shape("OUTPUT", (self.size, n))

    def init(self):
        self._rng = np.random.default_rng(self.seed or None)
        self._x = self.INPUT.reshape(-1)
        self._next = 0
        self.OUTPUT.fill(0)

    def tick(self):
        rows = self.OUTPUT.shape[0]
        if self.update_policy == "queue":
            self.OUTPUT[1:] = self.OUTPUT[:-1].copy()
            self.OUTPUT[0] = self._x
        elif self.update_policy == "circular":
            self.OUTPUT[self._next % rows] = self._x
            self._next = (self._next + 1) % rows
        else:
            self.OUTPUT[int(self._rng.integers(rows))] = self._x
        if self.debug:
            self.print("\n" + "\n".join(" ".join(f"{v:g}" for v in row) for row in self.OUTPUT))
