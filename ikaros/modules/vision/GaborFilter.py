"""GaborFilter: convolution with a Gabor kernel."""
import math

import numpy as np

from ikaros.module import Output, Parameter

from ._filters import KernelFilter, kernel_grid


class GaborFilter(KernelFilter):
    """Correlates the image with a Gabor kernel, the product of a Gaussian envelope
    exp(-(x'² + gamma² y'²) / 2σ²) and a grating cos(2π x' / lambda + phi), where
    x' = x cos(theta) + y sin(theta) and y' = -x sin(theta) + y cos(theta) (x to the right,
    y down, theta in radians). ``scale`` multiplies ``sigma`` and ``lambda``. The kernel
    is square, 2·ceil(3·σ·scale·max(1, 1/gamma)) + 1 pixels wide, so the envelope has
    fallen to about 1 % at its edge; this size is fixed when the model is built. As in
    Ikaros 2 the output is the part of the image where the whole kernel fits; a colour
    image is filtered plane by plane. FILTER is the kernel, GAUSSIAN its envelope and
    GRATING its grating. (The class has no kernel-size parameter, so this size rule is
    this module's own; OpenCV's getGaborKernel is not used because it stores its kernel
    flipped, for convolution.)"""

    scale = Parameter(1.0, "multiplies sigma and lambda")
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
        if self.sigma <= 0 or self.scale <= 0 or self.gamma <= 0:
            raise ValueError("sigma, scale and gamma must be above 0")
        k = 2 * math.ceil(3.0 * self.sigma * self.scale * max(1.0, 1.0 / self.gamma)) + 1
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
        sigma, wavelength = self.sigma * self.scale, getattr(self, "lambda") * self.scale
        c, s = math.cos(self.theta), math.sin(self.theta)
        xr, yr = x * c + y * s, -x * s + y * c
        self.GAUSSIAN[...] = np.exp(-(xr * xr + self.gamma ** 2 * yr * yr) / (2 * sigma ** 2))
        self.GRATING[...] = np.cos(2.0 * np.pi * xr / wavelength + self.phi)
        np.multiply(self.GAUSSIAN, self.GRATING, out=self.FILTER)
        self.kernel = self.FILTER
