"""CannyEdgeDetector: Canny edges on OpenCV."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import GrayImage, check_image, opencv
from ._edges import gaussian_derivative_kernels, non_maximum_suppression


class CannyEdgeDetector(Module):
    """Canny edge detection with OpenCV's Canny, on gradients from Gaussian-derivative
    filters. dx and dy are the derivatives of the gray image (the intensity of a colour
    one) smoothed by a Gaussian of standard deviation ``scale`` pixels, measured in the
    units of OpenCV's Canny on 8-bit images: a step from 0 to 1 (255 levels) gives 1020 at
    the pixels beside it, as the 3 x 3 Sobel kernel gives, whatever the scale. OUTPUT is the
    gradient magnitude, MAXIMA the magnitude at maxima across the edge that exceed ``T0``
    (0 elsewhere), and EDGES is 1 on the edges Canny finds by hysteresis: maxima above
    ``T2``, and maxima above ``T1`` connected to them (L2 magnitude, on dx and dy rounded to
    integers). So with the Ikaros 2 defaults a full-contrast step is a strong edge and a
    step of 0.2 a weak one. dGx and dGy are the kernels (2·ceil(3·scale) + 1 square) whose
    correlation with the image gives dx and dy. The image outputs have the input's size;
    the border is filled by reflection. (The Ikaros 2 class computed its gradients in its
    own way, so the same thresholds need not give exactly the same edges.)"""

    scale = Parameter(1.0, "standard deviation of the Gaussian smoothing, in pixels")
    T0 = Parameter(100.0, "MAXIMA keeps maxima above this magnitude")
    T1 = Parameter(200.0, "weak edges: above this magnitude and connected to a strong one")
    T2 = Parameter(800.0, "strong edges: above this magnitude")
    INPUT = Input("the image: gray (rows, cols), or colour (3, rows, cols) whose intensity "
                  "is used")
    EDGES = Output("1 on the edges, 0 elsewhere")
    MAXIMA = Output("the magnitude at maxima across the edge above T0, 0 elsewhere")
    OUTPUT = Output("the gradient magnitude")
    dx = Output("the derivative to the right (1020 beside a step from 0 to 1)")
    dy = Output("the derivative downwards")
    dGx = Output("the kernel whose correlation with the image gives dx")
    dGy = Output("the kernel whose correlation with the image gives dy")

    def configure(self):
        self.cv2 = opencv()
        kx, ky = gaussian_derivative_kernels(self.scale)
        # a step of 1 gives the sum of the kernel's positive half; make it 4 · 255
        gain = 1020.0 / float(kx[kx > 0].sum())
        self._kx, self._ky = kx * np.float32(gain), ky * np.float32(gain)

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape:
            check_image(shape)
            for name in ("EDGES", "MAXIMA", "OUTPUT", "dx", "dy"):
                self.set_output_shape(name, shape[-2:])
        self.set_output_shape("dGx", self._kx.shape)
        self.set_output_shape("dGy", self._ky.shape)

    def init(self):
        self._gray = GrayImage(self.INPUT)
        shape = self.OUTPUT.shape
        self._dx16, self._dy16 = np.zeros(shape, np.int16), np.zeros(shape, np.int16)
        self._edges = np.zeros(shape, np.uint8)
        self.dGx[...] = self._kx
        self.dGy[...] = self._ky

    def tick(self):
        cv2 = self.cv2
        gray = self._gray()
        cv2.filter2D(gray, -1, self._kx, dst=self.dx)
        cv2.filter2D(gray, -1, self._ky, dst=self.dy)
        cv2.magnitude(self.dx, self.dy, magnitude=self.OUTPUT)
        non_maximum_suppression(self.OUTPUT, self.dx, self.dy, self.MAXIMA, self.T0)
        np.copyto(self._dx16, np.clip(np.rint(self.dx), -32768, 32767), casting="unsafe")
        np.copyto(self._dy16, np.clip(np.rint(self.dy), -32768, 32767), casting="unsafe")
        cv2.Canny(self._dx16, self._dy16, self.T1, self.T2, edges=self._edges,
                  L2gradient=True)
        np.multiply(self._edges, 1.0 / 255.0, out=self.EDGES, casting="unsafe")
