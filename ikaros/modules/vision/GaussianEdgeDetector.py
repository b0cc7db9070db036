"""GaussianEdgeDetector: gradients from Gaussian-derivative filters."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import GrayImage, as_image, image_shape, opencv, shrunk
from ._gaussian_edges import Suppression, ValidGradient, ikaros2_kernels, warn_scale


class GaussianEdgeDetector(Module):
    """Edges from Gaussian-derivative filters, as Ikaros 2 computes them (its golden
    outputs show each step). dGx and dGy are the derivatives ∂G/∂x and ∂G/∂y of G =
    exp(-(x² + y²) / scale²), sampled on the offsets -r .. r, r = ceil(2 · scale) (for
    scale 1: 5 x 5, dGx = -2x · exp(-(x² + y²))). dx and dy are the correlations of the
    gray image (the intensity of a colour one) with them, on the part of the image where
    the kernels fit: every image output is 2r rows and columns smaller than INPUT (8 x 8 in
    gives 4 x 4). So dx is negative where the image gets brighter to the right. OUTPUT is
    the magnitude √(dx² + dy²) and ORIENTATION atan2(dx, dy) in radians (the angle from
    the downward y axis towards x: the arguments in that order, as the original's outputs
    show). MAXIMA is the
    magnitude after non-maximum suppression: the direction of (dx, dy) is rounded to the
    nearest of the 8 neighbours, and an inner pixel keeps its magnitude when it is above the
    neighbour behind it and at least the one ahead, else 0; the pixels on the border of the
    output keep their magnitude, as in the original. ``scale`` is fixed when the model is
    built. (The original runs only scale 1: with any other scale it cannot resolve two
    output sizes. The kernel's formula and size for other scales are this project's
    reading, with a warning.)"""

    scale = Parameter(1.0, "width of the Gaussian (G = exp(-(x² + y²) / scale²))")
    INPUT = Input("the image: gray (rows, cols), or colour (3, rows, cols) whose intensity "
                  "is used")
    ORIENTATION = Output("atan2(dx, dy), radians")
    MAXIMA = Output("the magnitude at maxima across the edge (and on the border), 0 "
                    "elsewhere")
    OUTPUT = Output("the gradient magnitude")
    dx = Output("the correlation with dGx (negative where the image gets brighter to the "
                "right)")
    dy = Output("the correlation with dGy")
    dGx = Output("the kernel ∂G/∂x")
    dGy = Output("the kernel ∂G/∂y")

    IMAGES = ("ORIENTATION", "MAXIMA", "OUTPUT", "dx", "dy")

    def configure(self):
        self.cv2 = opencv()
        self._kx, self._ky = ikaros2_kernels(self.scale)

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape:
            size = shrunk(image_shape(shape)[-2:], *self._kx.shape)
            for name in self.IMAGES:
                self.set_output_shape(name, size)
        self.set_output_shape("dGx", self._kx.shape)
        self.set_output_shape("dGy", self._ky.shape)

    def init(self):
        warn_scale(self)
        image = as_image(self.INPUT)
        self._gray = GrayImage(image)
        self._gradient = ValidGradient(self.cv2, self._kx, self._ky, image.shape[-2:])
        self._suppress = Suppression(self.OUTPUT.shape)
        self.dGx[...] = self._kx
        self.dGy[...] = self._ky

    def tick(self):
        gradient = self._gradient
        gradient(self._gray())
        np.copyto(self.dx, gradient.dx)
        np.copyto(self.dy, gradient.dy)
        self.cv2.magnitude(self.dx, self.dy, magnitude=self.OUTPUT)
        np.arctan2(self.dx, self.dy, out=self.ORIENTATION)
        self._suppress.directions(self.dx, self.dy)
        self._suppress(self.OUTPUT, self.MAXIMA)
