"""SumMatrix: sums a matrix over all elements, its rows or its columns."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class SumMatrix(Module):
    """Sums the input matrix. With direction ``all`` the output is one element, the sum of
    all elements; with ``column`` it has one element per column, the sum down that column;
    with ``row`` one element per row, the sum along that row. A 1-D input is one row; an input
    of higher rank is seen as rows of its last dimension. (The original crashed on
    the golden models, so no golden file shows its values; this follows the reference's
    description.) With ``debug`` the output is
    printed on every tick."""

    direction = Parameter("all", "all: one sum; column: a sum for each column; row: a sum "
                          "for each row", options="all/column/row")
    debug = Parameter(False, "print the output on every tick")
    INPUT = Input("the matrix to sum")
    OUTPUT = Output("the sum(s)")

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape is None:
            return
        cols = shape[-1] if shape else 1
        rows = int(np.prod(shape[:-1])) if len(shape) > 1 else 1
        size = {"all": 1, "column": cols, "row": rows}[self.direction]
        self.set_output_shape("OUTPUT", (size,))

    def init(self):
        x = self.INPUT
        self._m = x.reshape(1, -1) if x.ndim < 2 else x.reshape(-1, x.shape[-1])
        self._direction = self.direction

    def tick(self):
        if self._direction == "column":
            np.sum(self._m, axis=0, dtype=np.float32, out=self.OUTPUT)
        elif self._direction == "row":
            np.sum(self._m, axis=1, dtype=np.float32, out=self.OUTPUT)
        else:
            self.OUTPUT[0] = np.sum(self._m, dtype=np.float64)
        if self.debug:
            self.print(np.array2string(self.OUTPUT, precision=4))
