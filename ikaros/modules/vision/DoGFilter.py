"""DoGFilter: difference-of-Gaussians filter."""
import numpy as np

from ikaros.module import Output, Parameter

from ._filters import KernelFilter, kernel_grid, odd_kernel_size


class DoGFilter(KernelFilter):
    """Correlates the image with a difference of two Gaussians, G(sigma1) - G(sigma2),
    sampled on a ``kernel_size`` x ``kernel_size`` grid. With ``normalize`` each Gaussian
    is scaled to sum 1 on the grid, so the kernel sums to 0 and a flat image gives 0;
    without it each is the continuous Gaussian exp(-r²/2σ²) / (2πσ²). As in Ikaros 2 the
    output is the part of the image where the whole kernel fits (kernel_size - 1 rows and
    columns smaller); a colour image is filtered plane by plane. KERNEL is the kernel and
    PROFILE its middle row. The sigmas may change while the model runs."""

    sigma1 = Parameter(1.0, "standard deviation of the positive Gaussian, in pixels")
    sigma2 = Parameter(0.5, "standard deviation of the subtracted Gaussian, in pixels")
    kernel_size = Parameter(5, "width and height of the kernel, a positive odd number")
    normalize = Parameter(True, "scale each Gaussian to sum 1 on the grid")
    KERNEL = Output("the kernel", shape="@kernel_size, @kernel_size")
    PROFILE = Output("the middle row of the kernel", shape="1, @kernel_size")

    def kernel_shape(self):
        k = odd_kernel_size(self.kernel_size)
        return k, k

    def kernel_key(self):
        return self.sigma1, self.sigma2, self.normalize

    def make_kernel(self):
        x, y = kernel_grid(self.kernel_rows)
        r2 = x * x + y * y
        kernel = 0.0
        for sign, sigma in ((1.0, self.sigma1), (-1.0, self.sigma2)):
            g = np.exp(-r2 / (2.0 * sigma * sigma))
            g /= g.sum() if self.normalize else 2.0 * np.pi * sigma * sigma
            kernel = kernel + sign * g
        self.KERNEL[...] = kernel
        self.kernel = self.KERNEL
        self.PROFILE[0] = self.KERNEL[self.kernel_rows // 2]
