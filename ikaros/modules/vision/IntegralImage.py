"""IntegralImage: summed-area table."""
import numpy as np

from ikaros.module import Input, Module, Output

from ._cv import as_image, image_shape, opencv, planes


class IntegralImage(Module):
    """The summed-area table of the image: OUTPUT[r, c] is the sum of INPUT over rows 0..r
    and columns 0..c. The sums are made in float64 (OpenCV's integral) and stored as
    float32. A colour image gives the table of each plane; a vector is a one-row image
    (its running sum)."""

    INPUT = Input("the image: gray (rows, cols) or colour (3, rows, cols)")
    OUTPUT = Output("the summed-area table, the size of INPUT", shape="INPUT.shape")

    def configure(self):
        self.cv2 = opencv()

    def init(self):
        image = as_image(self.INPUT)
        image_shape(self.INPUT.shape)
        rows, cols = image.shape[-2:]
        self._sums = np.zeros((rows + 1, cols + 1), np.float64)
        self._table = self._sums[1:, 1:]
        self._pairs = list(zip(planes(image), planes(as_image(self.OUTPUT))))

    def tick(self):
        for src, dst in self._pairs:
            self.cv2.integral(src, sum=self._sums, sdepth=self.cv2.CV_64F)
            np.copyto(dst, self._table, casting="same_kind")
