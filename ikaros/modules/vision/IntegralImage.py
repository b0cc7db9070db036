"""IntegralImage: summed-area table."""
import numpy as np

from ikaros.module import Input, Module, Output

from ._cv import check_image, opencv, planes


class IntegralImage(Module):
    """The summed-area table of the image: OUTPUT[r, c] is the sum of INPUT over rows 0..r
    and columns 0..c. The sums are made in float64 (OpenCV's integral) and stored as
    float32. A colour image gives the table of each plane."""

    INPUT = Input("the image: gray (rows, cols) or colour (3, rows, cols)")
    OUTPUT = Output("the summed-area table, the size of INPUT", shape="INPUT.shape")

    def configure(self):
        self.cv2 = opencv()

    def init(self):
        check_image(self.INPUT.shape)
        rows, cols = self.INPUT.shape[-2:]
        self._sums = np.zeros((rows + 1, cols + 1), np.float64)
        self._table = self._sums[1:, 1:]
        self._pairs = list(zip(planes(self.INPUT), planes(self.OUTPUT)))

    def tick(self):
        for src, dst in self._pairs:
            self.cv2.integral(src, sum=self._sums, sdepth=self.cv2.CV_64F)
            np.copyto(dst, self._table, casting="same_kind")
