"""HarrisDetector: corner response from image gradients."""
import numpy as np

from ikaros.module import Input, Module, Output

from ._cv import as_image, image_shape, opencv, warn_one_row

BORDER = 2          # the window reaches 2 pixels up and left, 1 down and right
EPSILON = 1e-5


class HarrisDetector(Module):
    """The corner response of Ikaros 2's HarrisDetector from the gradient images DX and DY
    (for example the dx and dy of GaussianEdgeDetector or SobelEdgeDetector): with Sxx, Syy
    and Sxy the sums of DX², DY² and DX·DY over the 4 x 4 window of rows r - 2 .. r + 1 and
    columns c - 2 .. c + 1, OUTPUT[r, c] = (Sxx·Syy - Sxy²) / (Sxx + Syy + 1e-5), the
    determinant of the structure matrix over its trace. OUTPUT has the size of DX, with 0
    in a border 2 pixels wide all round. A vector is a one-row image, whose output is
    always 0 (as the original's golden outputs), with a warning."""

    DX = Input("the derivative to the right (rows, cols)")
    DY = Input("the derivative downwards (rows, cols)")
    OUTPUT = Output("the corner response, the size of DX, 0 in a 2-pixel border",
                    shape="DX.shape")

    def configure(self):
        self.cv2 = opencv()

    def init(self):
        shape = image_shape(self.DX.shape, "DX", gray=True)
        if image_shape(self.DY.shape, "DY", gray=True) != shape:
            raise ValueError(f"DX and DY must have the same size, not {self.DX.shape} and "
                             f"{self.DY.shape}")
        self._dx, self._dy, self._out = as_image(self.DX), as_image(self.DY), \
            as_image(self.OUTPUT)
        warn_one_row(self, "DX")
        self._products = [np.zeros(shape, np.float32) for _ in range(3)]
        self._sums = [np.zeros(shape, np.float32) for _ in range(3)]
        inner = (slice(BORDER, shape[0] - BORDER), slice(BORDER, shape[1] - BORDER))
        self._inner = inner
        self._scratch = np.zeros(self._out[inner].shape, np.float32)

    def tick(self):
        xx, yy, xy = self._products
        np.multiply(self._dx, self._dx, out=xx)
        np.multiply(self._dy, self._dy, out=yy)
        np.multiply(self._dx, self._dy, out=xy)
        for product, total in zip(self._products, self._sums):
            # anchor (2, 2) of a 4 x 4 box: offsets -2 .. +1 around each pixel
            self.cv2.boxFilter(product, -1, (4, 4), dst=total, anchor=(BORDER, BORDER),
                               normalize=False)
        sxx, syy, sxy = (s[self._inner] for s in self._sums)
        out, t = self._out[self._inner], self._scratch
        np.multiply(sxx, syy, out=out)
        np.multiply(sxy, sxy, out=t)
        out -= t
        np.add(sxx, syy, out=t)
        t += EPSILON
        out /= t
