"""Erode: 3 x 3 grey-level erosion."""
import numpy as np

from ._filters import ValidFilter


class Erode(ValidFilter):
    """Grey-level erosion: each pixel becomes the minimum of the 3 x 3 square around it
    (OpenCV's erode; the Ikaros 2 class description says maximum, but its erosion is the
    minimum). As in Ikaros 2 the output is the part of the image where the whole square
    fits, 2 rows and columns smaller; a colour image is eroded plane by plane."""

    _square = np.ones((3, 3), np.uint8)

    def kernel_shape(self):
        return 3, 3

    def filter(self, src, dst):
        self.cv2.erode(src, self._square, dst=dst)
