"""AttentionFocus: cuts a square around the focus out of the image."""
from ikaros.module import Input, Module, Output, Parameter

from ._cv import check_image, pixel_of, with_size


class AttentionFocus(Module):
    """Cuts the square of 2·output_radius + 1 pixels centred on the pixel at FOCUS out of
    the image, gray or colour. FOCUS is (x, y) as fractions of the image's width and height
    (0..1 from the left and top, the convention of the vision modules, as SaliencyMap's
    FOCUS gives it). Parts of the square outside the image are 0. (The Ikaros 2 class
    gives output_radius no default; 16 is this module's.)"""

    output_radius = Parameter(16, "the square is 2 · output_radius + 1 pixels wide")
    INPUT = Input("the image: gray (rows, cols) or colour (3, rows, cols)")
    FOCUS = Input("the centre: x, y as fractions of the width and height")
    OUTPUT = Output("the square around the focus, gray or colour as INPUT")

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if self.output_radius < 0:
            raise ValueError(f"output_radius must be at least 0, not {self.output_radius}")
        if shape:
            check_image(shape)
            side = 2 * self.output_radius + 1
            self.set_output_shape("OUTPUT", with_size(shape, side, side))

    def init(self):
        if self.FOCUS.size < 2:
            raise ValueError(f"FOCUS must hold x and y, not {self.FOCUS.size} value(s)")

    def tick(self):
        rows, cols = self.INPUT.shape[-2:]
        radius = self.output_radius
        row, col = pixel_of(float(self.FOCUS.flat[0]), float(self.FOCUS.flat[1]), rows, cols)
        top, left = row - radius, col - radius
        r0, c0 = max(top, 0), max(left, 0)
        r1, c1 = min(top + 2 * radius + 1, rows), min(left + 2 * radius + 1, cols)
        self.OUTPUT.fill(0.0)
        self.OUTPUT[..., r0 - top:r1 - top, c0 - left:c1 - left] = self.INPUT[..., r0:r1, c0:c1]
