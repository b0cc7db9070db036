"""ZeroCrossings: where the image changes sign."""
import numpy as np

from ikaros.module import Input, Module, Output

from ._cv import check_gray


class ZeroCrossings(Module):
    """Marks the zero crossings of an image (for example the output of LoGFilter): OUTPUT
    is 1 at a pixel whose value and that of its right or lower neighbour have opposite
    signs (their product is below 0), and 0 elsewhere."""

    INPUT = Input("the image (rows, cols)")
    OUTPUT = Output("1 at the zero crossings, 0 elsewhere", shape="INPUT.shape")

    def init(self):
        check_gray(self.INPUT.shape)
        rows, cols = self.INPUT.shape
        self._right = np.zeros((rows, cols - 1), bool)
        self._down = np.zeros((rows - 1, cols), bool)

    def tick(self):
        x, out = self.INPUT, self.OUTPUT
        np.less(x[:, :-1] * x[:, 1:], 0.0, out=self._right)
        np.less(x[:-1, :] * x[1:, :], 0.0, out=self._down)
        out.fill(0.0)
        out[:, :-1] += self._right
        out[:-1, :] += self._down
        np.minimum(out, 1.0, out=out)
