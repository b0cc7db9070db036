"""ChangeDetector: the absolute difference between successive images."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import check_image, with_size


class ChangeDetector(Module):
    """The absolute difference between the image of this tick and that of the previous
    tick, pixel by pixel (and plane by plane for a colour image). `border` pixels are dropped
    on every side, so the output is 2 · border rows and columns smaller. On the first tick
    there is no previous image and the output is 0."""

    border = Parameter(0, "pixels dropped on each side of the image", type="int")
    INPUT = Input("the image: gray (rows, cols) or colour (3, rows, cols)")
    OUTPUT = Output("|INPUT now - INPUT on the previous tick|, border pixels smaller on each "
                    "side")

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape is not None:
            check_image(shape)
            b = self.border
            if b < 0 or shape[-2] <= 2 * b or shape[-1] <= 2 * b:
                raise ValueError(f"border {b} leaves nothing of a {shape[-2]} x {shape[-1]} "
                                 f"image")
            self.set_output_shape("OUTPUT", with_size(shape, shape[-2] - 2 * b,
                                                      shape[-1] - 2 * b))

    def init(self):
        b = self.border
        self._now = self.INPUT[..., b:self.INPUT.shape[-2] - b, b:self.INPUT.shape[-1] - b]
        self._previous = None

    def tick(self):
        if self._previous is None:
            self._previous = self._now.copy()
        np.subtract(self._now, self._previous, out=self.OUTPUT)
        np.abs(self.OUTPUT, out=self.OUTPUT)
        np.copyto(self._previous, self._now)
