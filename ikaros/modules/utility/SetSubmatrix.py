"""SetSubmatrix: writes one matrix into a copy of another."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


def _as_matrix(x):
    """A 2-D view: a 1-D array is one row; higher ranks are rows of the last dimension."""
    return x.reshape(1, -1) if x.ndim < 2 else x.reshape(-1, x.shape[-1])


class SetSubmatrix(Module):
    """Copies DESTINATION to OUTPUT and then writes SOURCE into it with its top left corner
    at column ``offset_x`` and row ``offset_y``. A 1-D input is one row. The offsets can change
    while the model runs and may be negative; the part of SOURCE that falls outside the
    destination is left out, with a warning the first time (Ikaros 2 stopped the run when
    SOURCE did not fit at the offsets given at start-up). With ``debug`` the output is printed
    on every tick."""

    offset_x = Parameter(0, "column of the output where SOURCE's first column goes", type="int")
    offset_y = Parameter(0, "row of the output where SOURCE's first row goes", type="int")
    debug = Parameter(False, "print the output on every tick")
    SOURCE = Input("the matrix to write into the destination")
    DESTINATION = Input("the matrix that is copied to the output")
    OUTPUT = Output("DESTINATION with SOURCE written into it", size_set="DESTINATION")

    def init(self):
        self._src = _as_matrix(self.SOURCE)
        self._dst = _as_matrix(self.DESTINATION)
        self._out = _as_matrix(self.OUTPUT)
        self._warned = False

    def tick(self):
        self._out[...] = self._dst
        rows, cols = self._out.shape
        src_rows, src_cols = self._src.shape
        x0, y0 = self.offset_x, self.offset_y
        # The part of the source that lands inside the output.
        a_y, b_y = max(0, -y0), min(src_rows, rows - y0)
        a_x, b_x = max(0, -x0), min(src_cols, cols - x0)
        if (a_y, b_y, a_x, b_x) != (0, src_rows, 0, src_cols) and not self._warned:
            self._warned = True
            self.warning(f"SOURCE ({src_rows} x {src_cols}) at offset ({x0}, {y0}) does not "
                         f"fit inside DESTINATION ({rows} x {cols}); the part outside is "
                         f"left out")
        if b_y > a_y and b_x > a_x:
            self._out[y0 + a_y:y0 + b_y, x0 + a_x:x0 + b_x] = self._src[a_y:b_y, a_x:b_x]
        if self.debug:
            self.print(np.array2string(self.OUTPUT, precision=4))
