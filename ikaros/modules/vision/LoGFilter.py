"""LoGFilter: Laplacian-of-Gaussian filter."""
import numpy as np

from ikaros.module import Output, Parameter

from ._filters import KernelFilter, balance, kernel_grid, odd_kernel_size


class LoGFilter(KernelFilter):
    """Correlates the image with the Laplacian of a Gaussian of standard deviation
    ``sigma``, (r² - 2σ²) / σ⁴ · exp(-r²/2σ²) / (2πσ²), sampled on a ``kernel_size`` x
    ``kernel_size`` grid (negative in the centre, so a bright spot gives a negative
    response). With ``normalize``, as in Ikaros 2, the kernel's positive entries are scaled
    to sum 1 and its negative entries to sum -1 (so a flat image gives 0). As in Ikaros 2
    the output is the part of the image where the whole kernel fits (kernel_size - 1 rows
    and columns smaller); a colour image is filtered plane by plane. KERNEL is the kernel
    and PROFILE its middle row. ZeroCrossings finds the edges in the result. (kernel_size must be odd here, so that the kernel has a centre pixel;
    what Ikaros 2 does with an even size is not in the reference.)"""

    sigma = Parameter(1.0, "standard deviation of the Gaussian, in pixels")
    kernel_size = Parameter(5, "width and height of the kernel, a positive odd number")
    normalize = Parameter(True, "scale the positive entries to sum 1 and the negative "
                          "ones to sum -1")
    KERNEL = Output("the kernel", shape="@kernel_size, @kernel_size")
    PROFILE = Output("the middle row of the kernel", shape="1, @kernel_size")

    def kernel_shape(self):
        k = odd_kernel_size(self.kernel_size)
        return k, k

    def kernel_key(self):
        return self.sigma, self.normalize

    def make_kernel(self):
        x, y = kernel_grid(self.kernel_rows)
        r2, s2 = x * x + y * y, self.sigma * self.sigma
        kernel = (r2 - 2.0 * s2) / (s2 * s2) * np.exp(-r2 / (2.0 * s2)) / (2.0 * np.pi * s2)
        self.KERNEL[...] = balance(kernel) if self.normalize else kernel
        self.kernel = self.KERNEL
        self.PROFILE[0] = self.KERNEL[self.kernel_rows // 2]
