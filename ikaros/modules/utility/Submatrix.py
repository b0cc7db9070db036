"""Submatrix: a rectangular part of a matrix, optionally shifted."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Submatrix(Module):
    """Outputs the part of the input matrix with columns x0 <= x < x1 and rows y0 <= y < y1.
    With ``kernel_size`` k > 0 the region is instead what a k x k filter leaves valid: (k-1)/2
    (rounded down) columns and rows are cut from each side. ``x1`` = 0 means up to the last
    column and ``y1`` = 0 up to the last row, so the defaults output the whole input (in
    Ikaros 2 they gave an empty output). A 1-D input is one row: only x0 and x1 apply and the
    output is 1-D. When SHIFT is connected the region's content is shifted instead: output
    element (y, x) is region element (y + dy, x + dx), or 0 where that is outside the region,
    with dx = int(offset_x + direction * SHIFT[0]) and dy = int(offset_y + direction *
    SHIFT[1]) (rounded toward 0). Ikaros 2 shifted from the input's top left corner whatever
    x0 and y0 were."""

    x0 = Parameter(0, "first column of the region", type="int")
    x1 = Parameter(0, "column after the last one of the region; 0 means the input's width",
                   type="int")
    y0 = Parameter(0, "first row of the region", type="int")
    y1 = Parameter(0, "row after the last one of the region; 0 means the input's height",
                   type="int")
    kernel_size = Parameter(0, "when above 0, the region a filter of this size leaves valid, "
                            "instead of x0, x1, y0, y1", type="int")
    offset_x = Parameter(0.0, "shift in x added to direction * SHIFT[0]")
    offset_y = Parameter(0.0, "shift in y added to direction * SHIFT[1]")
    direction = Parameter(1.0, "multiplies SHIFT: its sign gives the direction of the shift")
    INPUT = Input("the matrix")
    SHIFT = Input("[dx, dy]: shift the region's content by this much", optional=True)
    OUTPUT = Output("the region of the input (shifted when SHIFT is connected)")

    def _region(self, shape):
        """(y0, y1, x0, x1) for an input of this shape, or raise ValueError."""
        rows, cols = (1, shape[0]) if len(shape) == 1 else (int(np.prod(shape[:-1])), shape[-1])
        k = self.kernel_size
        if k > 0:
            h = (k - 1) // 2
            y0, y1, x0, x1 = h, rows - h, h, cols - h
        else:
            x0, x1 = self.x0, self.x1 or cols
            y0, y1 = self.y0, self.y1 or rows
        if len(shape) == 1:
            y0, y1 = 0, 1
        if not (0 <= x0 < x1 <= cols):
            raise ValueError(f"the columns {x0}..{x1} are not a non-empty range inside the "
                             f"input's {cols} columns")
        if not (0 <= y0 < y1 <= rows):
            raise ValueError(f"the rows {y0}..{y1} are not a non-empty range inside the "
                             f"input's {rows} rows")
        return y0, y1, x0, x1

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape is None:
            return
        y0, y1, x0, x1 = self._region(shape)
        self.set_output_shape("OUTPUT", (x1 - x0,) if len(shape) == 1 else (y1 - y0, x1 - x0))

    def init(self):
        x = self.INPUT
        matrix = x.reshape(1, -1) if x.ndim == 1 else x.reshape(-1, x.shape[-1])
        y0, y1, x0, x1 = self._region(x.shape)
        self._view = matrix[y0:y1, x0:x1]
        self._out = self.OUTPUT.reshape(self._view.shape)
        self._shift = None if self.SHIFT is None else self.SHIFT.reshape(-1)
        if self._shift is not None and self._shift.size < 2 and x.ndim > 1:
            self.fatal_error(f"SHIFT needs two elements [dx, dy]; it has {self._shift.size}")

    def tick(self):
        if self._shift is None:
            self._out[...] = self._view
            return
        s = self._shift
        dx = int(self.offset_x + self.direction * float(s[0]))
        dy = int(self.offset_y + self.direction * float(s[1])) if s.size > 1 else 0
        rows, cols = self._view.shape
        self._out.fill(0)
        # out[j, i] = view[j + dy, i + dx] where 0 <= j + dy < rows and 0 <= i + dx < cols
        j0, j1 = max(0, -dy), min(rows, rows - dy)
        i0, i1 = max(0, -dx), min(cols, cols - dx)
        if j1 > j0 and i1 > i0:
            self._out[j0:j1, i0:i1] = self._view[j0 + dy:j1 + dy, i0 + dx:i1 + dx]
