"""GaussianFilter: Gaussian blur with its kernel as outputs."""
import numpy as np

from ikaros.module import Output, Parameter

from ._filters import ValidFilter, odd_kernel_size


class GaussianFilter(ValidFilter):
    """Blurs the image with a Gaussian of standard deviation ``sigma`` pixels sampled on a
    ``kernel_size`` x ``kernel_size`` grid and scaled to sum 1 (OpenCV's
    ``getGaussianKernel``; the filter is applied as two 1-D passes). As in Ikaros 2 the
    output is the part of the image where the whole kernel fits: kernel_size - 1 rows and
    columns smaller. A colour image is filtered plane by plane. KERNEL is the 2-D kernel and
    PROFILE its middle row, as in Ikaros 2 (its golden outputs show it; the middle row sums
    to less than 1). ``sigma`` may change while the model runs;
    ``sigma`` <= 0 takes it from the kernel size (0.3 * ((kernel_size - 1) / 2 - 1) + 0.8)."""

    sigma = Parameter(1.0, "standard deviation of the Gaussian, in pixels")
    kernel_size = Parameter(5, "width and height of the kernel, a positive odd number")
    KERNEL = Output("the 2-D kernel (sums to 1)", shape="@kernel_size, @kernel_size")
    PROFILE = Output("the middle row of KERNEL", shape="1, @kernel_size")

    def kernel_shape(self):
        k = odd_kernel_size(self.kernel_size)
        return k, k

    def kernel_key(self):
        return (self.sigma,)

    def make_kernel(self):
        self._profile = self.cv2.getGaussianKernel(self.kernel_rows, self.sigma,
                                                   self.cv2.CV_32F)
        np.multiply(self._profile, self._profile.T, out=self.KERNEL)
        self.PROFILE[0] = self.KERNEL[self.kernel_rows // 2]

    def filter(self, src, dst):
        self.cv2.sepFilter2D(src, -1, self._profile, self._profile, dst=dst,
                             borderType=self.cv2.BORDER_REFLECT)
