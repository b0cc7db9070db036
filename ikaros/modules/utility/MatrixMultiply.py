"""MatrixMultiply: the matrix product of two inputs."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


def _product_shape(a, b):
    """The shape of a @ b (NumPy's matmul rules), or a ValueError."""
    if len(a) == 0 or len(b) == 0:
        raise ValueError("both inputs must be connected")
    inner_a = a[-1]
    inner_b = b[0] if len(b) == 1 else b[-2]
    if inner_a != inner_b:
        raise ValueError(f"cannot multiply {a} by {b}: INPUT1 has {inner_a} columns but "
                         f"INPUT2 has {inner_b} rows")
    rows = a[-2:-1] if len(a) >= 2 else ()
    cols = b[-1:] if len(b) >= 2 else ()
    batch = np.broadcast_shapes(tuple(a[:-2]), tuple(b[:-2]))
    return tuple(batch) + tuple(rows) + tuple(cols) or (1,)


class MatrixMultiply(Module):
    """Outputs the matrix product INPUT1 x INPUT2, of rows(INPUT1) rows and cols(INPUT2)
    columns; the columns of INPUT1 must equal the rows of INPUT2. With ``trans_2`` INPUT2 is
    transposed first, so INPUT1 x INPUT2^T. A 1-D INPUT1 is a row vector and a 1-D INPUT2 a
    column vector, and that dimension is left out of the output (a vector times a vector is
    a single element, their dot product); inputs of higher rank are stacks of matrices, as in
    NumPy's matmul."""

    trans_2 = Parameter(False, "transpose INPUT2 before multiplying")
    INPUT1 = Input("the left matrix")
    INPUT2 = Input("the right matrix")
    OUTPUT = Output("the matrix product")

    def _right_shape(self, b):
        if self.trans_2 and len(b) >= 2:
            return tuple(b[:-2]) + (b[-1], b[-2])
        return tuple(b)

    def set_sizes(self):
        a, b = self.input_shape("INPUT1"), self.input_shape("INPUT2")
        if a is None or b is None:
            return
        self.set_output_shape("OUTPUT", _product_shape(tuple(a), self._right_shape(b)))

    def init(self):
        self._trans = self.trans_2     # the output's shape follows trans_2 at build time

    def tick(self):
        b = self.INPUT2
        if self._trans and b.ndim >= 2:
            b = np.swapaxes(b, -1, -2)
        self.OUTPUT[...] = np.reshape(np.matmul(self.INPUT1, b), self.OUTPUT.shape)
