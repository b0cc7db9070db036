"""ZeroCrossings: where the image changes sign."""
import numpy as np

from ikaros.module import Input, Module, Output

from ._cv import check_gray


class ZeroCrossings(Module):
    """Marks the zero crossings of an image (for example the output of LoGFilter), as
    Ikaros 2 does: OUTPUT is 1 at the pixel (r, c) when the product of its value with that
    of the pixel below (r + 1, c), the pixel to the right (r, c + 1) or the pixel
    diagonally below-right (r + 1, c + 1) is 0 or less, and 0 elsewhere. The last row and
    the last column are always 0. (A pixel of value 0 next to any pixel therefore counts as
    a crossing.)"""

    INPUT = Input("the image (rows, cols)")
    OUTPUT = Output("1 at the zero crossings, 0 elsewhere", shape="INPUT.shape")

    def init(self):
        check_gray(self.INPUT.shape)
        rows, cols = self.INPUT.shape
        self._product = np.zeros((rows - 1, cols - 1), np.float32)
        self._crossing = np.zeros((rows - 1, cols - 1), bool)
        self._any = np.zeros((rows - 1, cols - 1), bool)

    def tick(self):
        x, product, crossing, found = self.INPUT, self._product, self._crossing, self._any
        here = x[:-1, :-1]
        found.fill(False)
        for neighbour in (x[1:, :-1], x[:-1, 1:], x[1:, 1:]):
            np.multiply(here, neighbour, out=product)
            np.less_equal(product, 0.0, out=crossing)
            found |= crossing
        self.OUTPUT.fill(0.0)
        self.OUTPUT[:-1, :-1] = found
