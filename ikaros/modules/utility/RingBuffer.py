"""RingBuffer: the recent history of a signal."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class RingBuffer(Module):
    """Keeps the last ``size`` values of the input (read as a flat vector of n elements) and
    outputs them as a matrix of n rows and ``size`` columns: row j is the history of input
    element j, oldest on the left and the current input in the last column. Columns not yet
    filled are 0. The reference says the original keeps the last ``size`` input vectors
    with the output holding them transposed; the original refused the sizes of the golden
    models, so no golden file shows its values, and the time order of the columns is this
    project's reading.
    ``buffersize``, the name used in the Ikaros 2 code, overrides ``size`` when given."""

    size = Parameter(10, "the number of past inputs kept (the number of columns)", type="int")
    buffersize = Parameter(None, "another name for size; overrides it when given", type="int")
    debug = Parameter(False, "print the buffer on every tick")
    INPUT = Input("the signal to record")
    OUTPUT = Output("one row per input element, one column per tick, newest last")

    def _length(self):
        n = self.buffersize if self.buffersize else self.size
        return max(1, int(n))

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape is not None:
            self.set_output_shape("OUTPUT", (int(np.prod(shape)), self._length()))

    def init(self):
        self._input = self.INPUT.reshape(-1)
        self.OUTPUT.fill(0)

    def tick(self):
        out = self.OUTPUT
        out[:, :-1] = out[:, 1:]        # NumPy copies overlapping slices safely
        out[:, -1] = self._input
        if self.debug:
            self.print(f"\n{out}")

    def command(self, name, x=0, y=0, value=None):
        if name == "reset":
            self.OUTPUT.fill(0)
