"""DoGFilter: difference-of-Gaussians filter."""
import numpy as np

from ikaros.module import Output, Parameter

from ._filters import KernelFilter, balance, kernel_grid, odd_kernel_size


class DoGFilter(KernelFilter):
    """Correlates the image with a difference of two Gaussians, G(sigma1) - G(sigma2),
    sampled on a ``kernel_size`` x ``kernel_size`` grid of offsets (x, y) from its centre,
    as Ikaros 2 does: each Gaussian is exp(-(x² + y²) / 2σ²) / (σ·√(2π)), the constant of
    the 1-D Gaussian, with π taken as 3 (its golden outputs fit 1/(σ·√6) to 1e-6, a defect
    that scales the kernel without ``normalize``): ``pi="exact"`` (this project's
    correction) uses π. With ``normalize`` the kernel's positive entries are
    then scaled to sum 1 and its negative entries to sum -1 (so it sums to 0 and a flat
    image gives 0). As in Ikaros 2 the output is the part of the image where the whole
    kernel fits (kernel_size - 1 rows and columns smaller); a colour image is filtered
    plane by plane. KERNEL is the kernel and PROFILE its middle row. The sigmas may change
    while the model runs. (kernel_size must be odd here, so that the kernel has a centre
    pixel; what Ikaros 2 does with an even size is not in the reference.)"""

    sigma1 = Parameter(1.0, "standard deviation of the positive Gaussian, in pixels")
    sigma2 = Parameter(0.5, "standard deviation of the subtracted Gaussian, in pixels")
    kernel_size = Parameter(5, "width and height of the kernel, a positive odd number")
    normalize = Parameter(True, "scale the positive entries to sum 1 and the negative "
                          "ones to sum -1")
    pi = Parameter("3", "the value of pi in the Gaussians' constant: 3, as the original "
                   "(a defect), or exact", options="3/exact")
    KERNEL = Output("the kernel", shape="@kernel_size, @kernel_size")
    PROFILE = Output("the middle row of the kernel", shape="1, @kernel_size")

    def kernel_shape(self):
        k = odd_kernel_size(self.kernel_size)
        return k, k

    def kernel_key(self):
        return self.sigma1, self.sigma2, self.normalize, self.pi

    def make_kernel(self):
        x, y = kernel_grid(self.kernel_rows)
        r2 = x * x + y * y
        pi = np.pi if self.pi == "exact" else 3.0
        kernel = 0.0
        for sign, sigma in ((1.0, self.sigma1), (-1.0, self.sigma2)):
            kernel = kernel + sign * np.exp(-r2 / (2.0 * sigma * sigma)) / (
                sigma * np.sqrt(2.0 * pi))
        self.KERNEL[...] = balance(kernel) if self.normalize else kernel
        self.kernel = self.KERNEL
        self.PROFILE[0] = self.KERNEL[self.kernel_rows // 2]
