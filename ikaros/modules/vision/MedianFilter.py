"""MedianFilter: median of each pixel's neighbourhood."""
from ikaros.module import Parameter, require

from ._filters import ValidFilter, odd_kernel_size


class MedianFilter(ValidFilter):
    """Replaces each pixel by the median of the ``kernel_size`` x ``kernel_size`` square
    around it. As in Ikaros 2 the output is the part of the image where the whole square
    fits (kernel_size - 1 rows and columns smaller); a colour image is filtered plane by
    plane. Sizes 3 and 5 use OpenCV's medianBlur, which takes float images only for these
    sizes; other sizes use SciPy's median_filter (``pip install 'ikaros[scipy]'``)."""

    kernel_size = Parameter(5, "width and height of the square, a positive odd number")

    def configure(self):
        super().configure()
        if self.kernel_size not in (3, 5):
            self._ndimage = require("scipy.ndimage", "scipy", extra="scipy")

    def kernel_shape(self):
        k = odd_kernel_size(self.kernel_size)
        return k, k

    def filter(self, src, dst):
        if self.kernel_rows in (3, 5):
            self.cv2.medianBlur(src, self.kernel_rows, dst=dst)
        else:
            self._ndimage.median_filter(src, size=self.kernel_rows, output=dst,
                                        mode="nearest")
