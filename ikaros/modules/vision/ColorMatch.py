"""ColorMatch: similarity of each pixel's colour to a learned prototype."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._colour import plane_inputs, plane_inputs_shape
from ._cv import pixel_of


class ColorMatch(Module):
    """How close each pixel's colour is to a prototype colour: OUTPUT = gain ·
    exp(-d² / 2 sigma²), where d is the Euclidean distance between the pixel's three
    values and the prototype, in the units of the input (for example L*a*b* from
    ColorTransform, where the default sigma of 25 suits); values below ``threshold`` are
    set to 0. The prototype starts at (target0, target1, target2), and is set there again
    whenever these parameters change. It is learned: on a tick when REINFORCEMENT (its
    first value) is above 0 and FOCUS (x, y, fractions of the width and height) is
    connected, the prototype moves towards the colour at the focus by alpha ·
    reinforcement of the difference. The colour is read from TARGETINPUT (or TARGETINPUT0..2)
    when connected, otherwise from the image itself. The image comes on INPUT
    (3, rows, cols) or on INPUT0..2."""

    alpha = Parameter(0.01, "learning rate of the prototype")
    sigma = Parameter(25.0, "width of the similarity, in the units of the input")
    gain = Parameter(1.0, "the output for a perfect match")
    threshold = Parameter(0.0, "outputs below this are set to 0")
    target0 = Parameter(0.0, "first value of the starting prototype")
    target1 = Parameter(0.0, "second value of the starting prototype")
    target2 = Parameter(0.0, "third value of the starting prototype")
    INPUT = Input("a colour image (3, rows, cols); or connect INPUT0, INPUT1 and INPUT2",
                  optional=True)
    INPUT0 = Input("the first plane (rows, cols), when INPUT is not connected",
                   optional=True)
    INPUT1 = Input("the second plane (rows, cols)", optional=True)
    INPUT2 = Input("the third plane (rows, cols)", optional=True)
    TARGETINPUT = Input("the image to learn colours from (3, rows, cols)", optional=True)
    TARGETINPUT0 = Input("its first plane, when TARGETINPUT is not connected", optional=True)
    TARGETINPUT1 = Input("its second plane", optional=True)
    TARGETINPUT2 = Input("its third plane", optional=True)
    FOCUS = Input("where to learn the colour: x, y (fractions of width and height)",
                  optional=True)
    REINFORCEMENT = Input("learn when above 0, at a rate alpha times it", optional=True)
    OUTPUT = Output("the similarity of each pixel's colour to the prototype (rows, cols)")

    def set_sizes(self):
        shape = plane_inputs_shape(self)
        plane_inputs_shape(self, "TARGETINPUT", optional=True)
        if shape:
            self.set_output_shape("OUTPUT", shape)

    def init(self):
        self._planes = plane_inputs(self)
        self._targets = plane_inputs(self, "TARGETINPUT") or self._planes
        self._start = None
        self._distance = np.zeros(self.OUTPUT.shape, np.float32)
        self._difference = np.zeros(self.OUTPUT.shape, np.float32)

    def tick(self):
        start = (self.target0, self.target1, self.target2)
        if start != self._start:
            self._start, self.prototype = start, np.array(start, np.float64)
        self._learn()
        d2, diff, out = self._distance, self._difference, self.OUTPUT
        d2.fill(0.0)
        for plane, value in zip(self._planes, self.prototype):
            np.subtract(plane, value, out=diff)
            diff *= diff
            d2 += diff
        np.multiply(d2, -0.5 / (self.sigma * self.sigma), out=out)
        np.exp(out, out=out)
        out *= self.gain
        out[out < self.threshold] = 0.0

    def _learn(self):
        if self.FOCUS is None or self.REINFORCEMENT is None or self.FOCUS.size < 2:
            return
        reinforcement = float(self.REINFORCEMENT.flat[0])
        if reinforcement <= 0:
            return
        rows, cols = self._targets[0].shape
        row, col = pixel_of(float(self.FOCUS.flat[0]), float(self.FOCUS.flat[1]), rows, cols)
        colour = np.array([p[row, col] for p in self._targets], np.float64)
        self.prototype += self.alpha * reinforcement * (colour - self.prototype)
