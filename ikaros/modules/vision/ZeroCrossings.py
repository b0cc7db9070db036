"""ZeroCrossings: where the image changes sign."""
import numpy as np

from ikaros.module import Input, Module, Output

from ._cv import as_image, image_shape, warn_one_row


class ZeroCrossings(Module):
    """Marks the zero crossings of an image (for example the output of LoGFilter), as
    Ikaros 2 does: OUTPUT is 1 at the pixel (r, c) when the product of its value with that
    of the pixel below (r + 1, c), the pixel to the right (r, c + 1) or the pixel
    diagonally below-right (r + 1, c + 1) is 0 or less, and 0 elsewhere. The last row and
    the last column are always 0. (A pixel of value 0 next to any pixel therefore counts as
    a crossing.) A vector is a one-row image, whose output is always 0 (the original's
    golden outputs), with a warning."""

    INPUT = Input("the image (rows, cols)")
    OUTPUT = Output("1 at the zero crossings, 0 elsewhere", shape="INPUT.shape")

    def init(self):
        image_shape(self.INPUT.shape, gray=True)
        self._image, self._out = as_image(self.INPUT), as_image(self.OUTPUT)
        rows, cols = self._image.shape
        warn_one_row(self)
        self._product = np.zeros((rows - 1, cols - 1), np.float32)
        self._crossing = np.zeros((rows - 1, cols - 1), bool)
        self._any = np.zeros((rows - 1, cols - 1), bool)

    def tick(self):
        x, product, crossing, found = self._image, self._product, self._crossing, self._any
        here = x[:-1, :-1]
        found.fill(False)
        for neighbour in (x[1:, :-1], x[:-1, 1:], x[1:, 1:]):
            np.multiply(here, neighbour, out=product)
            np.less_equal(product, 0.0, out=crossing)
            found |= crossing
        self._out.fill(0.0)
        self._out[:-1, :-1] = found
