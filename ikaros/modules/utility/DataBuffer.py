"""DataBuffer: a matrix of past inputs."""
import math

from ikaros.module import Input, Module, Output, Parameter

from .._crand import module_rand


class DataBuffer(Module):
    """Keeps ``size`` past inputs as the rows of a matrix (the input is read as one flat
    vector); rows that have not been written are 0. On every tick the current input
    replaces a row. As in Ikaros 2 (golden files), that row is chosen at random whatever
    ``update_policy`` says: row rand() % size, with rand() the C library's generator
    (glibc's), unseeded in Ikaros 2, so every run of an Ikaros 2 model gives the same rows:
    3, 6, 7, 5, 3, ... for size 10. Ikaros 2 draws all its modules' random numbers from
    that one generator, in the order the modules tick; here the modules of a network share
    one too, so a model whose only user of rand() is one DataBuffer gives the original's
    rows, and several users draw in the order this kernel runs them. ``seed`` gives the
    module a generator of its own, seeded as srand does (a negative seed gives a different
    run every time).

    ``honour_policy="yes"`` (this project's) makes the other policies work as their names
    say: circular writes rows 0, 1, 2, ... in turn and starts over at 0; queue puts the
    newest input in row 0 and moves the older ones one row down, dropping the oldest."""

    size = Parameter(10, "the number of inputs kept (rows of the output)", type="int")
    update_policy = Parameter("random", "which row the new input replaces (Ikaros 2 replaces "
                              "a random row whatever it says; see honour_policy)",
                              options="random/circular/queue")
    honour_policy = Parameter(False, "this project's: circular and queue work as their "
                              "names say (Ikaros 2 replaces a random row for every policy)")
    seed = Parameter(None, "seed of the C library generator (as srand); unset: Ikaros 2's "
                     "unseeded sequence; negative: a different run every time", type="int")
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
        self._rand = module_rand(self)
        self._x = self.INPUT.reshape(-1)
        self._next = 0
        self.OUTPUT.fill(0)

    def tick(self):
        rows = self.OUTPUT.shape[0]
        policy = self.update_policy if self.honour_policy else "random"
        if policy == "queue":
            self.OUTPUT[1:] = self.OUTPUT[:-1].copy()
            self.OUTPUT[0] = self._x
        elif policy == "circular":
            self.OUTPUT[self._next % rows] = self._x
            self._next = (self._next + 1) % rows
        else:
            self.OUTPUT[self._rand.rand() % rows] = self._x
        if self.debug:
            self.print("\n" + "\n".join(" ".join(f"{v:g}" for v in row) for row in self.OUTPUT))
