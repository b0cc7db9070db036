"""MatrixScale: zooms the content of a matrix about its centre."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


def _resample(x, out, src_x, src_y):
    """out[..., i, j] = x[..., src_y[i, j], src_x[i, j]] with the coordinates rounded to the
    nearest element (halves away from zero); 0 where the source falls outside."""
    sx = np.where(src_x >= 0, np.floor(src_x + 0.5), np.ceil(src_x - 0.5))
    sy = np.where(src_y >= 0, np.floor(src_y + 0.5), np.ceil(src_y - 0.5))
    m = x if x.ndim > 1 else x.reshape(1, -1)
    o = out if out.ndim > 1 else out.reshape(1, -1)
    rows, cols = m.shape[-2], m.shape[-1]
    inside = (sx >= 0) & (sx < cols) & (sy >= 0) & (sy < rows)
    o.fill(0)
    o[..., inside] = m[..., sy[inside].astype(np.intp), sx[inside].astype(np.intp)]


class MatrixScale(Module):
    """Scales the content of INPUT (an image, say) about its centre by the factor X (first
    element) horizontally and Y (first element) vertically: a factor of 2 shows the middle
    half of the input twice as large, 0.5 shrinks the whole input to half size in the
    middle. Each output element takes the input element nearest to the point that maps to
    it, the point centre + (offset from the centre) / factor; elements that come from
    outside the input are 0, and a negative factor mirrors. The centre is ((cols - 1) / 2,
    (rows - 1) / 2), so a factor of 1 (or -1) maps the matrix exactly onto itself (Ikaros 2
    used (cols / 2, rows / 2)). A factor of 0 gives an output of 0 and a warning once.
    Works on the last two axes, so a colour image (3, rows, cols) scales as a whole; a 1-D
    input is one row."""

    debug = Parameter(False, "print the factors on every tick")
    INPUT = Input("the matrix to scale")
    X = Input("the horizontal factor; its first element is used")
    Y = Input("the vertical factor; its first element is used")
    OUTPUT = Output("the scaled matrix", size_set="INPUT")

    def init(self):
        rows, cols = (self.INPUT.shape[-2], self.INPUT.shape[-1]) if self.INPUT.ndim > 1 \
            else (1, self.INPUT.shape[0])
        y, x = np.mgrid[0:rows, 0:cols].astype(np.float64)
        self._cx, self._cy = (cols - 1) / 2, (rows - 1) / 2
        self._dx, self._dy = x - self._cx, y - self._cy
        self._warned = False

    def tick(self):
        fx, fy = float(self.X.flat[0]), float(self.Y.flat[0])
        if self.debug:
            self.print(f"scale {fx:g} x {fy:g}")
        if fx == 0 or fy == 0 or not np.isfinite(fx) or not np.isfinite(fy):
            if not self._warned:
                self._warned = True
                self.warning(f"cannot scale by {fx:g} x {fy:g}; the output is 0")
            self.OUTPUT.fill(0)
            return
        _resample(self.INPUT, self.OUTPUT, self._cx + self._dx / fx, self._cy + self._dy / fy)
