"""MatrixRotation: turns the content of a matrix about its centre."""
import math

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


class MatrixRotation(Module):
    """Turns the content of INPUT (an image, say) about its centre by the angle ANGLE (its
    first element), in degrees or radians as ``angle_format`` says. A positive angle turns
    the content counterclockwise as seen with row 0 at the top (90 degrees is Flip's
    rotate-left for a square matrix). Each output element takes the input element nearest to
    the point that the turn brings to it; elements that come from outside the input are 0.
    The centre is the middle of the matrix, ((cols - 1) / 2, (rows - 1) / 2), so a half turn
    maps the matrix exactly onto itself (Ikaros 2 used (cols / 2, rows / 2), which shifted
    it by one element). Works on the last two axes, so a colour image (3, rows, cols) turns
    as a whole; a 1-D input is one row."""

    angle_format = Parameter("deg", "the unit of ANGLE", options="deg/rad")
    debug = Parameter(False, "print the angle on every tick")
    INPUT = Input("the matrix to turn")
    ANGLE = Input("the angle; its first element is used")
    OUTPUT = Output("the turned matrix", size_set="INPUT")

    def init(self):
        rows, cols = (self.INPUT.shape[-2], self.INPUT.shape[-1]) if self.INPUT.ndim > 1 \
            else (1, self.INPUT.shape[0])
        y, x = np.mgrid[0:rows, 0:cols].astype(np.float64)
        self._cx, self._cy = (cols - 1) / 2, (rows - 1) / 2
        self._dx, self._dy = x - self._cx, y - self._cy

    def tick(self):
        angle = float(self.ANGLE.flat[0])
        if self.angle_format == "deg":
            angle = math.radians(angle)
        c, s = math.cos(angle), math.sin(angle)
        src_x = self._cx + c * self._dx - s * self._dy
        src_y = self._cy + s * self._dx + c * self._dy
        _resample(self.INPUT, self.OUTPUT, src_x, src_y)
        if self.debug:
            self.print(f"angle {float(self.ANGLE.flat[0]):g} {self.angle_format}")
