"""MatrixScale: zooms the content of a matrix about its centre."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._resample import CENTRE_HELP, CENTRES, centre_offsets, resample


class MatrixScale(Module):
    """Scales the content of INPUT (an image, say) about its centre by the factor X (first
    element) horizontally and Y (first element) vertically: a factor of 2 shows the middle
    half of the input twice as large, 0.5 shrinks the whole input to half size in the
    middle. Each output element takes the input element nearest to the point that maps to
    it, the point centre + (offset from the centre) / factor; elements that come from
    outside the input are 0, and a negative factor mirrors. The centre is (cols / 2, rows /
    2), as in Ikaros 2 (golden files); ``centre="middle"`` (this project's) scales about
    ((cols - 1) / 2, (rows - 1) / 2), so that a factor of -1 maps the matrix exactly onto
    itself. A factor of 0 gives an output of 0 and a warning once.
    Works on the last two axes, so a colour image (3, rows, cols) scales as a whole; a 1-D
    input is one row."""

    centre = Parameter("half", CENTRE_HELP, options=CENTRES)
    debug = Parameter(False, "print the factors on every tick")
    INPUT = Input("the matrix to scale")
    X = Input("the horizontal factor; its first element is used")
    Y = Input("the vertical factor; its first element is used")
    OUTPUT = Output("the scaled matrix", size_set="INPUT")

    def init(self):
        self._cx, self._cy, self._dx, self._dy = centre_offsets(self.INPUT, self.centre)
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
        resample(self.INPUT, self.OUTPUT, self._cx + self._dx / fx, self._cy + self._dy / fy)
