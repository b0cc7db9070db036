"""HysteresisThresholding: strong edges and the weak edges next to them."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import check_gray, opencv


class HysteresisThresholding(Module):
    """Hysteresis thresholding of an edge image: OUTPUT is 1 where INPUT is above ``T2``
    (strong edges); then, ``iterations`` times, weak pixels (above ``T1``) within ``range``
    pixels (a square of side 2·range + 1) of an output pixel become 1 too. So a weak edge is
    followed up to range · iterations pixels from a strong one. The growth is a dilation
    (OpenCV), not a loop over pixels."""

    range = Parameter(1, "how far (pixels) a weak pixel may be from an output pixel")
    iterations = Parameter(1, "how many times the output grows into weak pixels")
    T1 = Parameter(0.3, "weak threshold")
    T2 = Parameter(0.6, "strong threshold")
    INPUT = Input("the edge image (rows, cols)")
    OUTPUT = Output("1 on the kept edges, 0 elsewhere", shape="INPUT.shape")

    def configure(self):
        self.cv2 = opencv()

    def init(self):
        check_gray(self.INPUT.shape)
        self._kept = np.zeros(self.INPUT.shape, np.uint8)
        self._weak = np.zeros(self.INPUT.shape, np.uint8)

    def tick(self):
        kept, weak = self._kept, self._weak
        np.greater(self.INPUT, self.T2, out=kept, casting="unsafe")
        np.greater(self.INPUT, self.T1, out=weak, casting="unsafe")
        square = np.ones((2 * self.range + 1,) * 2, np.uint8)
        for _ in range(self.iterations):
            self.cv2.dilate(kept, square, dst=kept)
            np.bitwise_and(kept, weak, out=kept)
        np.copyto(self.OUTPUT, kept)
