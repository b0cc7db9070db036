"""GaborFilter: convolution with a Gabor kernel."""
import math

import numpy as np

from ikaros.module import Output, Parameter

from ._filters import KernelFilter, kernel_grid


class GaborFilter(KernelFilter):
    """Correlates the image with a Gabor kernel and outputs the absolute value, as Ikaros 2
    does. The kernel is square, of radius int(2·scale + 0.5) pixels (5 x 5 by default); it
    is the product of a Gaussian envelope exp(-(x'² + gamma² y'²) / 2σ²) and a grating
    cos(2π x' / lambda + phi), where x' = x cos(theta) + y sin(theta) and
    y' = -x sin(theta) + y cos(theta) (x to the right, y down, from the kernel's centre,
    theta in radians); ``sigma`` and ``lambda`` are in pixels and are not multiplied by
    ``scale``, which sets only the size. As in Ikaros 2 the output is the part of the image
    where the whole kernel fits (2·radius rows and columns smaller); a colour image is
    filtered plane by plane. FILTER is the kernel, GAUSSIAN its envelope and GRATING its
    grating. (The reference gives the kernel's size, the absolute value and the parameter
    names; the envelope and grating above are the standard Gabor formulas, and whether
    Ikaros 2 writes them exactly so is not in the reference. The kernel size is fixed when
    the model is built.)"""

    scale = Parameter(1.0, "sets the kernel's radius, int(2·scale + 0.5) pixels")
    gamma = Parameter(0.5, "aspect ratio of the envelope (its width along the grating's "
                      "stripes is sigma / gamma)")
    # 'lambda' is a Python keyword: the value is read with getattr(self, "lambda")
    lambda_ = Parameter(4.0, "wavelength of the grating, in pixels", name="lambda")
    theta = Parameter(0.0, "orientation: the grating varies along this angle, in radians")
    phi = Parameter(1.57, "phase of the grating, in radians")
    sigma = Parameter(1.0, "standard deviation of the envelope, in pixels")
    FILTER = Output("the Gabor kernel, GAUSSIAN times GRATING")
    GAUSSIAN = Output("the Gaussian envelope of the kernel")
    GRATING = Output("the grating of the kernel")

    def kernel_shape(self):
        if self.sigma <= 0 or self.scale < 0 or getattr(self, "lambda") == 0:
            raise ValueError("sigma must be above 0, scale 0 or more and lambda not 0")
        k = 2 * int(2.0 * self.scale + 0.5) + 1
        return k, k

    def set_sizes(self):
        super().set_sizes()
        for name in ("FILTER", "GAUSSIAN", "GRATING"):
            self.set_output_shape(name, self.kernel_shape())

    def kernel_key(self):
        return (self.scale, self.gamma, getattr(self, "lambda"), self.theta, self.phi,
                self.sigma)

    def make_kernel(self):
        x, y = kernel_grid(self.kernel_rows)
        sigma, wavelength = self.sigma, getattr(self, "lambda")
        c, s = math.cos(self.theta), math.sin(self.theta)
        xr, yr = x * c + y * s, -x * s + y * c
        self.GAUSSIAN[...] = np.exp(-(xr * xr + self.gamma ** 2 * yr * yr) / (2 * sigma ** 2))
        self.GRATING[...] = np.cos(2.0 * np.pi * xr / wavelength + self.phi)
        np.multiply(self.GAUSSIAN, self.GRATING, out=self.FILTER)
        self.kernel = self.FILTER

    def filter(self, src, dst):
        super().filter(src, dst)
        np.abs(dst, out=dst)
