"""Dilate: 3 x 3 grey-level dilation."""
import numpy as np

from ._filters import ValidFilter


class Dilate(ValidFilter):
    """Grey-level dilation: each pixel becomes the maximum of the 3 x 3 square around it
    (OpenCV's dilate). As in Ikaros 2 the output is the part of the image where the whole
    square fits, 2 rows and columns smaller; a colour image is dilated plane by plane."""

    _square = np.ones((3, 3), np.uint8)

    def kernel_shape(self):
        return 3, 3

    def filter(self, src, dst):
        self.cv2.dilate(src, self._square, dst=dst)
