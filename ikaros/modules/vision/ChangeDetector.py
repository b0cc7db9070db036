"""ChangeDetector: the difference between successive images."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import as_image, image_shape, with_size


class ChangeDetector(Module):
    """The absolute difference between the image of this tick and that of the previous
    tick, pixel by pixel (and plane by plane for a colour image; a vector is a one-row
    image). Before the first tick the previous image is 0, so the first output is the
    image's own size. ``border`` pixels are dropped on every side, so the output is
    2 · border rows and columns smaller. Ikaros 2 takes the absolute value with the integer
    function, so it gives the whole part of the difference: |0.5| gives 0, |-1| 1 and 2.7
    gives 2 (its golden outputs show it; a defect). That is the default
    (``difference="truncated"``); ``difference="exact"`` (this project's correction) gives
    the difference itself."""

    border = Parameter(0, "pixels dropped on each side of the image", type="int")
    difference = Parameter("truncated", "truncated: the whole part of |now - before|, as the "
                           "original (a defect); exact: |now - before|",
                           options="truncated/exact")
    INPUT = Input("the image: gray (rows, cols), colour (3, rows, cols) or a vector (one "
                  "row)")
    OUTPUT = Output("|INPUT now - INPUT on the previous tick|, border pixels smaller on each "
                    "side")

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape is not None:
            one_row = len(shape) == 1
            shape = image_shape(shape)
            b = self.border
            if b < 0 or shape[-2] <= 2 * b or shape[-1] <= 2 * b:
                raise ValueError(f"border {b} leaves nothing of a {shape[-2]} x {shape[-1]} "
                                 f"image")
            size = with_size(shape, shape[-2] - 2 * b, shape[-1] - 2 * b)
            self.set_output_shape("OUTPUT", size[-1:] if one_row else size)

    def init(self):
        b, image = self.border, as_image(self.INPUT)
        self._now = image[..., b:image.shape[-2] - b, b:image.shape[-1] - b]
        self._out = as_image(self.OUTPUT)
        self._previous = np.zeros(self._now.shape, np.float32)

    def tick(self):
        out = self._out
        np.subtract(self._now, self._previous, out=out)
        np.abs(out, out=out)
        if self.difference == "truncated":
            np.trunc(out, out=out)
        np.copyto(self._previous, self._now)
