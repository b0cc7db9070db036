"""Maxima: finds the local maxima of a matrix."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Maxima(Module):
    """Marks the local maxima of the input with 1 in OUTPUT (0 elsewhere) and lists them in
    POINTS. An element is a local maximum when it is at least ``threshold`` and not smaller
    than any of its 8 neighbours; as in Ikaros 2, elements on the border of the matrix are
    never maxima. A 1-D input is one row, all border, so it has no maxima, as in Ikaros 2
    (golden files); ``vectors="along"`` (this project's) searches it along its length (2
    neighbours each; the first and last elements are the border). Each row of POINTS is x,
    y, value, with x = (column + 0.5) / columns and y = (row + 0.5) / rows, so both lie in
    0..1; rows after the last listed point are 0 and POINT_COUNT gives the number listed.
    At most ``max_points`` maxima are listed: the first ones in row-major order, or, with
    ``sort_points``, the largest ones in order of decreasing value, those of equal value in
    row-major order (the golden files show that order for equal values; for different
    values the order is this project's reading)."""

    max_points = Parameter(10, "the largest number of maxima listed in POINTS", type="int")
    threshold = Parameter(0.0, "elements below this value are never maxima")
    sort_points = Parameter(False, "list the largest maxima, largest first, instead of the "
                            "first ones in row-major order")
    vectors = Parameter("border", "a 1-D input: border (Ikaros 2: one row, all border, no "
                        "maxima) or along (searched along its length)",
                        options="border/along")
    INPUT = Input("the matrix to search")
    OUTPUT = Output("1 at each local maximum, 0 elsewhere", size_set="INPUT")
    POINTS = Output("one row x, y, value per listed maximum (x and y in 0..1)",
                    shape="@max_points, 3")
    POINT_COUNT = Output("the number of maxima listed in POINTS", size="1")

    def init(self):
        x = self.INPUT
        if x.ndim <= 1:
            self._m = x.reshape(1, -1)
            self._one_d = True
        else:
            self._m = x.reshape(-1, x.shape[-1])
            self._one_d = False
        self._marks = self.OUTPUT.reshape(self._m.shape)

    def tick(self):
        m = self._m
        rows, cols = m.shape
        marks = self._marks
        marks.fill(0)
        self.POINTS.fill(0)
        if self._one_d and self.vectors == "border":
            self.POINT_COUNT[0] = 0
            return
        if self._one_d:
            if cols < 3:
                self.POINT_COUNT[0] = 0
                return
            inner = m[:, 1:-1]
            mask = (inner >= m[:, :-2]) & (inner >= m[:, 2:])
            r0 = 0
        else:
            if rows < 3 or cols < 3:
                self.POINT_COUNT[0] = 0
                return
            inner = m[1:-1, 1:-1]
            mask = np.ones(inner.shape, dtype=bool)
            for dy in (0, 1, 2):
                for dx in (0, 1, 2):
                    if dy != 1 or dx != 1:
                        mask &= inner >= m[dy:dy + rows - 2, dx:dx + cols - 2]
            r0 = 1
        mask &= inner >= np.float32(self.threshold)
        marks[r0:r0 + mask.shape[0], 1:-1] = mask
        ys, xs = np.nonzero(mask)
        ys = ys + r0
        xs = xs + 1
        values = m[ys, xs]
        if self.sort_points:
            order = np.argsort(-values, kind="stable")
            ys, xs, values = ys[order], xs[order], values[order]
        n = max(0, min(len(values), self.POINTS.shape[0]))
        self.POINTS[:n, 0] = (xs[:n] + 0.5) / cols
        self.POINTS[:n, 1] = (ys[:n] + 0.5) / rows
        self.POINTS[:n, 2] = values[:n]
        self.POINT_COUNT[0] = n
