"""ColorMatch: similarity of each pixel's colour to a learned prototype."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._colour import plane_inputs, plane_inputs_shape
from ._cv import pixel_of


# exp of an exponent below this is under the smallest normal float32, and 0 in the original
SMALLEST_EXPONENT = np.float32(np.log(np.finfo(np.float32).tiny))


class ColorMatch(Module):
    """How close each pixel's colour is to a prototype colour.

    With ``similarity="graded"`` (the default in an Ikaros 3 file) it computes as Ikaros 3
    does (its golden outputs fix the formula): each colour (c0, c1, c2) is divided by its
    sum c0 + c1 + c2, and OUTPUT = gain · exp(-sigma · d), where d is the Euclidean
    distance between the pixel's and the prototype's divided colours. A pixel whose sum is
    not above ``threshold`` gives 0 (the golden outputs show this for a sum of 0 and that
    values below ``threshold`` are not cut; that the test is on the sum is this module's
    reading); a prototype whose sum is 0 counts as (0, 0, 0).

    Ikaros 2's OUTPUT is binary (``similarity="binary"``, the default in an Ikaros 2 file):
    ``gain`` where the pixel's sum is above ``threshold`` and exp(-sigma · d²), with d² the
    squared distance of the divided colours, is above ``threshold`` in single precision,
    where an exponent below -87.34 gives 0 (the smallest normal float); 0 elsewhere. Its
    golden outputs fit this in every case (the default prototype (0, 0, 0) with sigma 25,
    other targets, sigma and gain); with threshold 0, as there, a pixel is gain unless its
    sum is not positive or sigma · d² > 87.34. Which comparisons use ``threshold`` when it
    is not 0 is this module's reading. Set ``similarity="graded"`` for the similarity
    itself (this project's correction in an Ikaros 2 file).

    The prototype starts at (target0, target1, target2), and is set there again whenever
    these parameters change. It is learned: on a tick when REINFORCEMENT (its first value)
    is above 0 and FOCUS is connected, after OUTPUT is computed, the prototype becomes
    p + alpha · reinforcement · (t - p), where p is the prototype divided by its sum and t
    the colour at the focus as it is (not divided), so the next tick's OUTPUT shows it. The
    colour is read from TARGETINPUT (or TARGETINPUT0..2) when connected, otherwise from the
    image itself. FOCUS is a position (x, y) in fractions of the width and height
    (docs/images.md); the golden case, (1, 0) in a 2 x 2 image, reads column 1 of row 0
    under this convention as under pixel indices. The image comes on INPUT (3, rows, cols)
    or on INPUT0..2 (a vector is a one-row plane)."""

    alpha = Parameter(0.01, "learning rate of the prototype")
    sigma = Parameter(25.0, "how fast the similarity falls with the distance of the "
                      "chromaticities")
    gain = Parameter(1.0, "the output for a perfect match")
    threshold = Parameter(0.0, "pixels whose channel sum is not above this give 0")
    similarity = Parameter("binary", "binary: gain or 0, as Ikaros 2; graded: gain · "
                           "exp(-sigma · d), as Ikaros 3", options="binary/graded",
                           default_v3="graded")
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
        shape = self.OUTPUT.shape
        self._sum = np.zeros(shape, np.float64)
        self._distance = np.zeros(shape, np.float64)
        self._difference = np.zeros(shape, np.float64)
        self._sum32 = np.zeros(shape, np.float32)
        self._d2, self._diff32 = np.zeros(shape, np.float32), np.zeros(shape, np.float32)
        self._normal, self._out = np.zeros(shape, bool), np.zeros(shape, bool)

    def tick(self):
        start = (self.target0, self.target1, self.target2)
        if start != self._start:
            self._start, self.prototype = start, np.array(start, np.float64)
        prototype = chromaticity(self.prototype)
        if self.similarity == "binary":
            self._binary(prototype)
            self._learn(prototype)
            return
        total, d2, diff = self._sum, self._distance, self._difference
        np.add(self._planes[0], self._planes[1], out=total)
        total += self._planes[2]
        valid = total > self.threshold
        np.copyto(total, 1.0, where=~valid)
        d2.fill(0.0)
        for plane, value in zip(self._planes, prototype):
            np.divide(plane, total, out=diff)
            diff -= value
            diff *= diff
            d2 += diff
        np.sqrt(d2, out=d2)
        d2 *= -self.sigma
        np.exp(d2, out=d2)
        d2 *= self.gain
        np.multiply(d2, valid, out=self.OUTPUT)
        self._learn(prototype)

    def _binary(self, prototype):
        """Ikaros 2's output, in single precision on buffers made once."""
        total, d2, diff, out = self._sum32, self._d2, self._diff32, self._out
        np.add(self._planes[0], self._planes[1], out=total)
        total += self._planes[2]
        threshold = np.float32(self.threshold)
        d2.fill(0.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            for plane, value in zip(self._planes, prototype.astype(np.float32)):
                np.divide(plane, total, out=diff)
                diff -= value
                diff *= diff
                d2 += diff
        d2 *= np.float32(-self.sigma)                  # the exponent
        np.greater_equal(d2, SMALLEST_EXPONENT, out=self._normal)
        np.exp(d2, out=d2, where=self._normal)
        np.copyto(d2, 0.0, where=~self._normal)        # below the smallest normal: 0
        np.greater(d2, threshold, out=out)
        out &= total > threshold
        np.multiply(out, np.float32(self.gain), out=self.OUTPUT)

    def _learn(self, prototype):
        if self.FOCUS is None or self.REINFORCEMENT is None or self.FOCUS.size < 2:
            return
        reinforcement = float(self.REINFORCEMENT.flat[0])
        if reinforcement <= 0:
            return
        rows, cols = self._targets[0].shape
        row, col = pixel_of(float(self.FOCUS.flat[0]), float(self.FOCUS.flat[1]), rows, cols)
        colour = np.array([p[row, col] for p in self._targets], np.float64)
        self.prototype = prototype + self.alpha * reinforcement * (colour - prototype)


def chromaticity(colour: np.ndarray) -> np.ndarray:
    """A colour divided by the sum of its three values; (0, 0, 0) when the sum is 0."""
    total = colour.sum()
    return colour / total if total != 0 else np.zeros(3)
