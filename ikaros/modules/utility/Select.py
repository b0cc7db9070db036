"""Select: picks elements of the input by index."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Select(Module):
    """Copies selected elements of the input to a 1-D output, in the order listed in
    ``select``. A single row of indices (``select="3 2 1"``) selects elements of the input
    read as a flat array (for a 1-D input, its elements; Ikaros 2 read only the first row of
    a matrix). A matrix of n rows with two columns x, y (``select="3 0; 2 1; 1 4"``) selects
    INPUT[y][x] from a matrix input (a 1-D input counts as one row). Indices are 0-based and
    fractions are truncated. An index outside the input gives 0 in that position and a
    warning (once)."""

    select = Parameter(None, "the indices to pick: one row of flat indices, or n rows of "
                       "x y pairs", type="matrix")
    INPUT = Input("the array or matrix to select from")
    OUTPUT = Output("the selected elements, one per index (or pair)")

    def configure(self):
        sel = np.asarray(self.select, dtype=np.float32)
        if sel.size == 0:
            raise ValueError("Select needs a select parameter with at least one index")
        self.set_output_shape("OUTPUT", (self._count(sel),))

    @staticmethod
    def _pairs(sel):
        return sel.ndim == 2 and sel.shape[0] > 1

    def _count(self, sel):
        if self._pairs(sel):
            if sel.shape[1] != 2:
                raise ValueError(f"a select matrix needs two columns (x y), not {sel.shape[1]}")
            return sel.shape[0]
        return sel.size

    def init(self):
        self._warned = False
        x = self.INPUT
        self._flat = x.reshape(-1)
        cols = x.shape[-1] if x.ndim >= 1 else 1
        self._matrix = x.reshape(-1, cols)

    def tick(self):
        sel = np.asarray(self.select)
        out = self.OUTPUT
        if self._pairs(sel):
            xs = sel[:, 0].astype(np.int64)
            ys = sel[:, 1].astype(np.int64)
            rows, cols = self._matrix.shape
            ok = (xs >= 0) & (xs < cols) & (ys >= 0) & (ys < rows)
            n = min(out.size, ok.size)
            out.fill(0)
            good = np.nonzero(ok[:n])[0]
            out[good] = self._matrix[ys[good], xs[good]]
        else:
            idx = sel.reshape(-1).astype(np.int64)
            ok = (idx >= 0) & (idx < self._flat.size)
            n = min(out.size, ok.size)
            out.fill(0)
            good = np.nonzero(ok[:n])[0]
            out[good] = self._flat[idx[good]]
        if not ok.all() and not self._warned:
            self._warned = True
            bad = sel[~ok] if self._pairs(sel) else sel.reshape(-1)[~ok]
            self.warning(f"selection indices out of range of the input "
                         f"{tuple(self.INPUT.shape)}: {bad.tolist()}; they give 0")
