"""ArgMax: the position of the largest element."""
import numpy as np

from ikaros.module import Input, Module, Output


class ArgMax(Module):
    """Outputs the position (x, y) of the largest element of the input: x is its column and
    y its row. For a 1-D input x is the index and y is 0; an input of higher rank is read as
    a matrix whose rows are all leading dimensions laid end to end. When several elements
    share the largest value the first (row by row) wins. VALUE holds the largest value."""

    INPUT = Input("the matrix or vector to search")
    OUTPUT = Output("the position of the largest element: x (column), y (row)", size="2")
    VALUE = Output("the largest value", size="1")

    def init(self):
        if self.INPUT.size == 0:
            self.fatal_error("ArgMax needs a non-empty input")
            return
        self._cols = self.INPUT.shape[-1] if self.INPUT.ndim >= 2 else self.INPUT.size
        self._flat = self.INPUT.reshape(-1)

    def tick(self):
        index = int(np.argmax(self._flat))
        row, col = divmod(index, self._cols)
        self.OUTPUT[0] = col
        self.OUTPUT[1] = row
        self.VALUE[0] = self._flat[index]
