"""CoarseCoder: a tile or Gaussian code of a two-dimensional value."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class CoarseCoder(Module):
    """Codes a two-dimensional value (INPUT[0] = x, INPUT[1] = y, each in min..max) as activity
    in an output_size x output_size map, x along the columns and y along the rows, as Ikaros
    2 does (the class is not in Ikaros 3). The value is first mapped to a map position
    (px, py): min goes to ``radius`` and max to output_size - 1 - radius, so the whole code
    stays inside the map (values outside min..max are clipped to it). With type ``tile`` the
    cells whose column lies in round(px - radius) .. round(px + radius) and whose row lies in
    round(py - radius) .. round(py + radius) are 1 and the rest 0; with ``normalize`` the
    active cells are 1 / their number, so the map sums to 1. With type ``gaussian`` each cell
    is exp(-d), d being its distance in cells from (px, py): Ikaros 2's "Gaussian" (the
    golden files show it), whose width does not follow radius. ``profile="normal"`` (this
    project's) makes it a true Gaussian, exp(-d^2 / (2 radius^2)), a radius of 0 then making
    the nearest cell 1. With ``normalize`` a gaussian map is divided by its sum (this
    project's reading: no reference shows whether Ikaros 2 normalizes its gaussian code).
    When max equals min every value codes as min, with a warning."""

    type = Parameter("tile", "tile: a square of 1s; gaussian: a Gaussian bump",
                     options="tile/gaussian")
    output_size = Parameter(10, "the number of rows and of columns of the map", type="int")
    radius = Parameter(1.0, "the half-width of the tile, or the standard deviation of the "
                       "Gaussian, in cells")
    min = Parameter(0.0, "the value coded at the first position")
    max = Parameter(1.0, "the value coded at the last position")
    normalize = Parameter(False, "scale the code so that the map sums to 1")
    profile = Parameter("distance", "the gaussian type's profile: distance: exp(-d), as Ikaros "
                        "2; normal: exp(-d^2 / (2 radius^2))", options="distance/normal")
    INPUT = Input("the value to code: [x, y]")
    OUTPUT = Output("the coarse code", size_param_x="output_size", size_param_y="output_size")

    def init(self):
        if self.INPUT.size != 2:
            self.fatal_error(f"INPUT must have 2 elements [x, y], not {self.INPUT.size}")
            return
        self._x = self.INPUT.reshape(-1)
        n = self.OUTPUT.shape[0]
        self._rows, self._cols = np.mgrid[0:n, 0:n].astype(np.float64)
        self._warned = False

    def _position(self):
        """The map position (px, py) of the input."""
        lo, hi = self.min, self.max
        r = max(self.radius, 0.0)
        scale = self.OUTPUT.shape[0] - (1 + 2 * r)
        if hi == lo:
            if not self._warned:
                self._warned = True
                self.warning("max equals min; every value is coded as min")
            f = np.zeros(2)
        else:
            f = (np.clip(self._x.astype(np.float64), min(lo, hi), max(lo, hi)) - lo) / (hi - lo)
        p = r + scale * f
        return float(p[0]), float(p[1])

    def tick(self):
        out = self.OUTPUT
        n = out.shape[0]
        px, py = self._position()
        r = max(self.radius, 0.0)
        if self.type == "gaussian" and (r > 0 or self.profile == "distance"):
            d2 = (self._cols - px) ** 2 + (self._rows - py) ** 2
            out[...] = np.exp(-np.sqrt(d2)) if self.profile == "distance" else \
                np.exp(-d2 / (2 * r * r))
            if self.normalize:
                total = float(out.sum(dtype=np.float64))
                if total > 0:
                    out *= np.float32(1 / total)
            return
        out.fill(0)
        if self.type == "gaussian":             # a normal profile of radius 0: the nearest cell
            r = 0.0
        i0, i1 = int(np.floor(px - r + 0.5)), int(np.floor(px + r + 0.5))
        j0, j1 = int(np.floor(py - r + 0.5)), int(np.floor(py + r + 0.5))
        i0, i1, j0, j1 = max(i0, 0), min(i1, n - 1), max(j0, 0), min(j1, n - 1)
        if i1 < i0 or j1 < j0:
            return
        count = (i1 - i0 + 1) * (j1 - j0 + 1)
        out[j0:j1 + 1, i0:i1 + 1] = 1.0 / count if self.normalize else 1.0
