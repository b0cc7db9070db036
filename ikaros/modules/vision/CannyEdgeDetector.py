"""CannyEdgeDetector: Canny edges, as Ikaros 2 and as today's Ikaros 3 interface has it."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import GrayImage, as_image, image_shape, opencv, shrunk, warn_other_version
from ._edges import gaussian_derivative_kernels, non_maximum_suppression
from ._gaussian_edges import (Suppression, ValidGradient, hysteresis, ikaros2_kernels,
                              warn_scale)

IKAROS2_PARAMETERS = ("scale", "T0", "T1", "T2")
IKAROS3_PARAMETERS = ("sigma", "low_threshold", "high_threshold")
IMAGES = ("EDGES", "MAXIMA", "OUTPUT", "dx", "dy")
SCALE = 1000.0          # derivatives per pixel to the int16 levels given to OpenCV's Canny


class CannyEdgeDetector(Module):
    """Canny edge detection. OUTPUT is 1 on the edges and 0 elsewhere in both versions.

    **Ikaros 2 file** (the golden outputs of Ikaros 2 show each step): the gradient is that
    of GaussianEdgeDetector with the same ``scale``: the correlations of the gray image
    (the intensity of a colour one) with dGx and dGy, the derivatives of exp(-(x² + y²) /
    scale²) on 5 x 5 offsets for scale 1, on the part of the image where they fit, so every
    image output is 4 rows and columns smaller than INPUT (8 x 8 in gives 4 x 4). EDGES is
    the gradient magnitude where it is above ``T0``, and 0 elsewhere. dx and dy are the
    direction of the gradient rounded to one of the 8 neighbours, as the column and row
    offsets (-1, 0 or 1) of the neighbour ahead (0 where the magnitude is not above T0).
    MAXIMA is EDGES after non-maximum suppression (an inner pixel keeps its value when it is
    above the neighbour behind it and at least the one ahead; the border keeps EDGES).
    OUTPUT is 1 at the inner pixels (not the border of the output) whose MAXIMA are above
    ``T2``, and at those above ``T1`` connected to them through such pixels (8-neighbours).
    The defaults (T0 = 100) suit images of 0..255; for images of 0..1 the magnitude of a
    full step is about 1. (The golden cases have no weak pixel inside the border, so how
    the original follows weak edges is this project's reading. The original runs only
    scale 1; other scales warn, as in GaussianEdgeDetector.)

    **Ikaros 3 file**: today's Ikaros 3 class has INPUT, OUTPUT of the input's size and
    the parameters ``sigma`` (1), ``low_threshold`` (0.1) and ``high_threshold`` (0.3);
    only that interface is known, so the computation is this project's reading: dx and dy
    are the derivatives (intensity per pixel; a ramp of slope 1 gives 1) of the image
    blurred by a Gaussian of standard deviation ``sigma``, as correlations with dGx and
    dGy (2·ceil(3·sigma) + 1 square), of the input's size with the border filled by
    reflection; EDGES is their magnitude and MAXIMA the magnitude at maxima across the edge
    above low_threshold; OUTPUT is OpenCV's Canny hysteresis on them (L2 magnitude): maxima
    above high_threshold, and those above low_threshold connected to them. A step of 1
    blurred with sigma 1 gives a magnitude of about 0.4, a strong edge.

    The parameters of the other version are not used, with a warning when the module sets
    them."""

    scale = Parameter(1.0, "Ikaros 2: width of the Gaussian (exp(-(x² + y²) / scale²))")
    T0 = Parameter(100.0, "Ikaros 2: EDGES keeps magnitudes above this")
    T1 = Parameter(200.0, "Ikaros 2: weak edges are above this and connected to a strong one")
    T2 = Parameter(800.0, "Ikaros 2: strong edges are above this")
    sigma = Parameter(1.0, "Ikaros 3: standard deviation of the Gaussian blur, pixels")
    low_threshold = Parameter(0.1, "Ikaros 3: weak edges: a gradient above this (intensity "
                              "per pixel), connected to a strong one")
    high_threshold = Parameter(0.3, "Ikaros 3: strong edges: a gradient above this")
    INPUT = Input("the image: gray (rows, cols), or colour (3, rows, cols) whose intensity "
                  "is used")
    EDGES = Output("the gradient magnitude (Ikaros 2: where above T0)")
    MAXIMA = Output("the magnitude at maxima across the edge, 0 elsewhere")
    OUTPUT = Output("1 on the edges, 0 elsewhere")
    dx = Output("Ikaros 2: the column offset of the gradient direction (-1, 0, 1); Ikaros 3: "
                "the derivative to the right")
    dy = Output("Ikaros 2: the row offset of the gradient direction; Ikaros 3: the "
                "derivative downwards")
    dGx = Output("the kernel whose correlation with the image gives the x derivative")
    dGy = Output("the kernel whose correlation with the image gives the y derivative")

    def configure(self):
        self.cv2 = opencv()
        self._v3 = self.dialect == "3"
        make = gaussian_derivative_kernels if self._v3 else ikaros2_kernels
        self._kx, self._ky = make(self.sigma if self._v3 else self.scale)

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape:
            size = image_shape(shape)[-2:]
            if not self._v3:
                size = shrunk(size, *self._kx.shape)
            for name in IMAGES:
                self.set_output_shape(name, size)
        self.set_output_shape("dGx", self._kx.shape)
        self.set_output_shape("dGy", self._ky.shape)

    def init(self):
        warn_other_version(self, IKAROS2_PARAMETERS, IKAROS3_PARAMETERS)
        if not self._v3:
            warn_scale(self)
        image = as_image(self.INPUT)
        self._gray = GrayImage(image)
        self.dGx[...] = self._kx
        self.dGy[...] = self._ky
        shape = self.OUTPUT.shape
        if self._v3:
            self._dx16, self._dy16 = np.zeros(shape, np.int16), np.zeros(shape, np.int16)
            self._edges = np.zeros(shape, np.uint8)
        else:
            self._gradient = ValidGradient(self.cv2, self._kx, self._ky, image.shape[-2:])
            self._suppress = Suppression(shape)
            self._above = np.zeros(shape, bool)

    def tick(self):
        if self._v3:
            self._tick_v3()
            return
        gradient, suppress = self._gradient, self._suppress
        gradient(self._gray())
        self.cv2.magnitude(gradient.dx, gradient.dy, magnitude=self.EDGES)
        np.greater(self.EDGES, self.T0, out=self._above)
        self.EDGES *= self._above
        suppress.directions(gradient.dx, gradient.dy)
        suppress.offsets(self.dx, self.dy)
        self.dx *= self._above
        self.dy *= self._above
        suppress(self.EDGES, self.MAXIMA)
        hysteresis(self.cv2, self.MAXIMA, self.T1, self.T2, self.OUTPUT)

    def _tick_v3(self):
        cv2 = self.cv2
        gray = self._gray()
        cv2.filter2D(gray, -1, self._kx, dst=self.dx, borderType=cv2.BORDER_REFLECT)
        cv2.filter2D(gray, -1, self._ky, dst=self.dy, borderType=cv2.BORDER_REFLECT)
        cv2.magnitude(self.dx, self.dy, magnitude=self.EDGES)
        non_maximum_suppression(self.EDGES, self.dx, self.dy, self.MAXIMA, self.low_threshold)
        for src, dst in ((self.dx, self._dx16), (self.dy, self._dy16)):
            np.copyto(dst, np.clip(np.rint(src * np.float32(SCALE)), -32768, 32767),
                      casting="unsafe")
        cv2.Canny(self._dx16, self._dy16, self.low_threshold * SCALE,
                  self.high_threshold * SCALE, edges=self._edges, L2gradient=True)
        np.multiply(self._edges, np.float32(1 / 255), out=self.OUTPUT, casting="unsafe")
