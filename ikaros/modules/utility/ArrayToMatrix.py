"""ArrayToMatrix: lays a vector out as the rows of a matrix."""
import math

from ikaros.module import Input, Module, Output, Parameter


class ArrayToMatrix(Module):
    """Reshapes the input into a matrix with ``array_length`` columns: elements 0 to
    array_length-1 form row 0, the next array_length elements row 1, and so on. The matrix has
    as many rows as needed to hold the whole input; when the input size is not a multiple of
    array_length the last row is padded with 0 (the original wrote past the end of its output
    in that case)."""

    array_length = Parameter(16, "the number of columns of the output", type="int")
    INPUT = Input("the array to lay out; a matrix input is read row by row")
    OUTPUT = Output("the input as a matrix of array_length columns")

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape is None:
            return
        if self.array_length < 1:
            raise ValueError(f"array_length must be at least 1, not {self.array_length}")
        n = math.prod(shape)
        rows = max(1, -(-n // self.array_length))
        self.set_output_shape("OUTPUT", (rows, self.array_length))

    def init(self):
        self.OUTPUT.fill(0)
        self._src = self.INPUT.reshape(-1)
        self._dst = self.OUTPUT.reshape(-1)[:self._src.size]

    def tick(self):
        self._dst[...] = self._src
