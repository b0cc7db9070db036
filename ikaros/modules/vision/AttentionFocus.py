"""AttentionFocus: cuts a square around the focus out of the image."""
from ikaros.module import Input, Module, Output, Parameter

from ._cv import as_image, image_shape, warn_one_row, with_size


class AttentionFocus(Module):
    """Cuts the square of 2·output_radius + 1 pixels centred on the focus out of the image,
    gray or colour (a vector is a one-row image). FOCUS is (x, y) as fractions of the
    image's width and height, 0..1 from the left and top; the centre is the pixel in column
    trunc(x · cols) and row trunc(y · rows). Parts of the square outside the image are 0.
    As in Ikaros 2 (its golden outputs show it), the image's first row and first column are
    never copied either (a defect: they come out 0, so a one-row image always gives 0); that
    is the default (``edge="skipped"``), and ``edge="copied"`` (this project's correction)
    copies them. Ikaros 2's default output_radius gives a square of 31 pixels (radius
    15)."""

    output_radius = Parameter(15, "the square is 2 · output_radius + 1 pixels wide")
    edge = Parameter("skipped", "skipped: the image's first row and column are left 0, as "
                     "the original (a defect); copied: they are copied",
                     options="skipped/copied")
    INPUT = Input("the image: gray (rows, cols), colour (3, rows, cols) or a vector (one "
                  "row)")
    FOCUS = Input("the centre: x, y as fractions of the width and height")
    OUTPUT = Output("the square around the focus, gray or colour as INPUT")

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if self.output_radius < 0:
            raise ValueError(f"output_radius must be at least 0, not {self.output_radius}")
        if shape:
            side = 2 * self.output_radius + 1
            self.set_output_shape("OUTPUT", with_size(image_shape(shape), side, side))

    def init(self):
        if self.FOCUS.size < 2:
            raise ValueError(f"FOCUS must hold x and y, not {self.FOCUS.size} value(s)")
        self._image = as_image(self.INPUT)
        if self.edge == "skipped":
            warn_one_row(self)

    def tick(self):
        rows, cols = self._image.shape[-2:]
        radius = self.output_radius
        self.OUTPUT.fill(0.0)
        x, y = float(self.FOCUS.flat[0]) * cols, float(self.FOCUS.flat[1]) * rows
        if not (abs(x) < 1e9 and abs(y) < 1e9):             # nan, infinite or far away
            return
        col, row = int(x), int(y)                           # truncated, as in the original
        top, left = row - radius, col - radius
        first = 1 if self.edge == "skipped" else 0
        r0, c0 = max(top, first), max(left, first)
        r1, c1 = min(top + 2 * radius + 1, rows), min(left + 2 * radius + 1, cols)
        if r1 > r0 and c1 > c0:
            self.OUTPUT[..., r0 - top:r1 - top, c0 - left:c1 - left] = \
                self._image[..., r0:r1, c0:c1]
