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
    NumPy's matmul.

    In an Ikaros 2 file ``trans_2`` computes as Ikaros 2 does (golden files), which is not
    the product with the transpose: for INPUT1 A (M x K) and INPUT2 B (N x K) the output (M
    x N) holds, read column by column, the product of A with B's values read as a K x N
    matrix: out.flat[i + j M] = sum over k of A[i, k] B.flat[j + k N]. For a square
    output that is the transpose of A B' where B' is B's values in K rows of N. The golden
    files show only a 2 x 2 output; this formula is this project's reading of the
    original's computation for other sizes. ``trans_2_result="transpose"`` (this
    project's, and the default in an Ikaros 3 file, whose MatrixMultiply has no trans_2)
    gives A x B^T."""

    trans_2 = Parameter(False, "transpose INPUT2 before multiplying (see trans_2_result)")
    trans_2_result = Parameter("original", "what trans_2 gives for matrices: original (Ikaros "
                               "2's computation) or transpose (A x B^T)",
                               options="original/transpose", default_v3="transpose")
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
        a, b = self.INPUT1, self.INPUT2
        if self._trans and a.ndim == b.ndim == 2 and self.trans_2_result == "original":
            k, n = a.shape[1], b.shape[0]
            product = np.matmul(a, b.reshape(k, n))         # B's values in K rows of N
            self.OUTPUT.reshape(-1)[...] = product.T.reshape(-1)   # written column by column
            return
        if self._trans and b.ndim >= 2:
            b = np.swapaxes(b, -1, -2)
        self.OUTPUT[...] = np.reshape(np.matmul(a, b), self.OUTPUT.shape)
