"""HarrisDetector: Harris corner response from image gradients."""
import numpy as np

from ikaros.module import Input, Module, Output

from ._cv import check_gray, opencv, shrunk


class HarrisDetector(Module):
    """The Harris corner response from the gradient images DX and DY (for example the dx
    and dy of GaussianEdgeDetector or SobelEdgeDetector): with A, B and C the sums of
    DX², DY² and DX·DY over the 3 x 3 square around a pixel, the response is
    A·B - C² - 0.04·(A + B)². Corners give large positive values, edges negative ones. As in
    Ikaros 2 the output is the part where the square fits, 2 rows and columns smaller."""

    DX = Input("the derivative to the right (rows, cols)")
    DY = Input("the derivative downwards (rows, cols)")
    OUTPUT = Output("the corner response, 2 rows and columns smaller than DX")

    k = 0.04

    def configure(self):
        self.cv2 = opencv()

    def set_sizes(self):
        dx, dy = self.input_shape("DX"), self.input_shape("DY")
        if dx and dy:
            check_gray(dx, "DX")
            check_gray(dy, "DY")
            if dx != dy:
                raise ValueError(f"DX and DY must have the same size, not {dx} and {dy}")
            self.set_output_shape("OUTPUT", shrunk(dx, 3))

    def init(self):
        shape = self.DX.shape
        self._products = [np.zeros(shape, np.float32) for _ in range(3)]
        self._sums = [np.zeros(shape, np.float32) for _ in range(3)]
        self._valid = [s[1:-1, 1:-1] for s in self._sums]
        self._scratch = np.zeros(self.OUTPUT.shape, np.float32)

    def tick(self):
        cv2 = self.cv2
        xx, yy, xy = self._products
        np.multiply(self.DX, self.DX, out=xx)
        np.multiply(self.DY, self.DY, out=yy)
        np.multiply(self.DX, self.DY, out=xy)
        for product, total in zip(self._products, self._sums):
            cv2.boxFilter(product, -1, (3, 3), dst=total, normalize=False)
        a, b, c = self._valid
        out, t = self.OUTPUT, self._scratch
        np.multiply(a, b, out=out)
        np.multiply(c, c, out=t)
        out -= t
        np.add(a, b, out=t)
        t *= t
        t *= self.k
        out -= t
