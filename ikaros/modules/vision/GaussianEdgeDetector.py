"""GaussianEdgeDetector: gradients from Gaussian-derivative filters."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import GrayImage, check_image, opencv
from ._edges import gaussian_derivative_kernels, non_maximum_suppression


class GaussianEdgeDetector(Module):
    """Edges from Gaussian-derivative filters: dx and dy are the derivatives of the gray
    image (the intensity of a colour one) smoothed by a Gaussian of standard deviation
    ``scale`` pixels, in intensity per pixel (a ramp of slope 1 gives 1). OUTPUT is the
    gradient magnitude, ORIENTATION its direction atan2(dy, dx) in radians (y points down),
    and MAXIMA the magnitude where it is a maximum across the edge (non-maximum
    suppression, 0 elsewhere). dGx and dGy are the filter kernels, 2·ceil(3·scale) + 1
    square. The image outputs have the input's size; the border is filled by reflection
    (OpenCV's filter2D). ``scale`` is fixed when the model is built."""

    scale = Parameter(1.0, "standard deviation of the Gaussian, in pixels")
    INPUT = Input("the image: gray (rows, cols), or colour (3, rows, cols) whose intensity "
                  "is used")
    ORIENTATION = Output("the gradient direction atan2(dy, dx), radians")
    MAXIMA = Output("the magnitude at maxima across the edge, 0 elsewhere")
    OUTPUT = Output("the gradient magnitude")
    dx = Output("the derivative to the right")
    dy = Output("the derivative downwards")
    dGx = Output("the kernel whose correlation with the image gives dx")
    dGy = Output("the kernel whose correlation with the image gives dy")

    def configure(self):
        self.cv2 = opencv()
        self._kx, self._ky = gaussian_derivative_kernels(self.scale)

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape:
            check_image(shape)
            for name in ("ORIENTATION", "MAXIMA", "OUTPUT", "dx", "dy"):
                self.set_output_shape(name, shape[-2:])
        self.set_output_shape("dGx", self._kx.shape)
        self.set_output_shape("dGy", self._ky.shape)

    def init(self):
        self._gray = GrayImage(self.INPUT)
        self.dGx[...] = self._kx
        self.dGy[...] = self._ky

    def tick(self):
        gray = self._gray()
        self.cv2.filter2D(gray, -1, self._kx, dst=self.dx)
        self.cv2.filter2D(gray, -1, self._ky, dst=self.dy)
        self.cv2.cartToPolar(self.dx, self.dy, magnitude=self.OUTPUT)
        np.arctan2(self.dy, self.dx, out=self.ORIENTATION)
        non_maximum_suppression(self.OUTPUT, self.dx, self.dy, self.MAXIMA)
