"""MatrixRotation: turns the content of a matrix about its centre."""
import math

from ikaros.module import Input, Module, Output, Parameter

from ._resample import CENTRE_HELP, CENTRES, centre_offsets, resample


class MatrixRotation(Module):
    """Turns the content of INPUT (an image, say) about its centre by the angle ANGLE (its
    first element), in degrees or radians as ``angle_format`` says. A positive angle turns
    the content counterclockwise as seen with row 0 at the top (90 degrees is Flip's
    rotate-left for a square matrix). Each output element takes the input element nearest to
    the point that the turn brings to it (rounded to the nearest element); elements that
    come from outside the input are 0. The centre is (cols / 2, rows / 2), as in Ikaros 2
    (golden files), which for an even size is half an element right of and below the
    middle, so that a half turn shifts the matrix by one element; ``centre="middle"``
    (this project's) turns about ((cols - 1) / 2, (rows - 1) / 2), so a half turn maps the
    matrix exactly onto itself. Works on the last two axes, so a colour image (3, rows,
    cols) turns as a whole; a 1-D input is one row."""

    angle_format = Parameter("deg", "the unit of ANGLE", options="deg/rad")
    centre = Parameter("half", CENTRE_HELP, options=CENTRES)
    debug = Parameter(False, "print the angle on every tick")
    INPUT = Input("the matrix to turn")
    ANGLE = Input("the angle; its first element is used")
    OUTPUT = Output("the turned matrix", size_set="INPUT")

    def init(self):
        self._cx, self._cy, self._dx, self._dy = centre_offsets(self.INPUT, self.centre)

    def tick(self):
        angle = float(self.ANGLE.flat[0])
        if self.angle_format == "deg":
            angle = math.radians(angle)
        c, s = math.cos(angle), math.sin(angle)
        src_x = self._cx + c * self._dx - s * self._dy
        src_y = self._cy + s * self._dx + c * self._dy
        resample(self.INPUT, self.OUTPUT, src_x, src_y)
        if self.debug:
            self.print(f"angle {float(self.ANGLE.flat[0]):g} {self.angle_format}")
