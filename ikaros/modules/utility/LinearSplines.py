"""LinearSplines: piecewise-linear functions of the input."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class LinearSplines(Module):
    """Applies piecewise-linear functions to INPUT element by element. ``points`` is a matrix
    whose rows are control points: columns 0 and 1 hold the (x, y) points of the first
    function, columns 2 and 3 those of the second, and so on, each sorted by increasing x.
    Element i of the input uses function i mod (number of functions). Between two points the
    output is interpolated linearly; below the first point it is the first y, above the last
    point the last y. Where two points share an x the function jumps there, and at that x it
    takes the later point's y. A function with fewer points than the others is padded with
    rows of zeros: its points end at the first row whose x is smaller than the x before it
    (Ikaros 2 used the padding as points and gave 0 past the last real point)."""

    points = Parameter("0 0; 1 1", "rows of (x, y) pairs: columns 2k and 2k+1 hold the points "
                       "of function k, sorted by x", type="matrix")
    INPUT = Input("the values to map")
    OUTPUT = Output("the function values", size_set="INPUT")

    def init(self):
        self._table = None
        self._functions()

    def _functions(self):
        """(xs, ys) per function, from the current points (cached until they change)."""
        p = np.asarray(self.points, dtype=np.float64)
        if p.ndim == 1:
            p = p.reshape(1, -1)
        if self._table is not None and np.array_equal(p, self._table[0]):
            return self._table[1]
        if p.shape[1] < 2 or p.shape[1] % 2:
            raise ValueError(f"points needs an even number of columns, (x, y) pairs; it has "
                             f"{p.shape[1]}")
        functions = []
        for k in range(p.shape[1] // 2):
            xs, ys = p[:, 2 * k], p[:, 2 * k + 1]
            drops = np.nonzero(np.diff(xs) < 0)[0]
            end = drops[0] + 1 if drops.size else len(xs)
            functions.append((xs[:end], ys[:end]))
        self._table = (p.copy(), functions)
        return functions

    @staticmethod
    def _evaluate(x, xs, ys):
        if len(xs) == 1:
            return np.full_like(x, ys[0])
        # the segment [xs[j], xs[j+1]] with xs[j] <= x, taking the last such j
        j = np.clip(np.searchsorted(xs, x, side="right") - 1, 0, len(xs) - 2)
        x0, x1, y0, y1 = xs[j], xs[j + 1], ys[j], ys[j + 1]
        width = x1 - x0
        slope = np.divide(y1 - y0, width, out=np.zeros_like(width), where=width != 0)
        y = y0 + slope * (x - x0)
        y = np.where(x < xs[0], ys[0], y)
        return np.where(x >= xs[-1], ys[-1], y)

    def tick(self):
        try:
            functions = self._functions()
        except ValueError as e:
            self.fatal_error(str(e))
            return
        x = self.INPUT.reshape(-1).astype(np.float64)
        out = self.OUTPUT.reshape(-1)
        n = len(functions)
        for k, (xs, ys) in enumerate(functions):
            out[k::n] = self._evaluate(x[k::n], xs, ys)
