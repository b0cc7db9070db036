"""ColorClassifier: pixels of one hue in rg chromaticity."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import check_gray, opencv

SIZE = 256

# cv2.magnitude is within a few float32 ulps of the exact saturation; a pixel whose
# magnitude lies this far (relative) outside the saturation bounds is certainly outside them
MARGIN = 1e-4
# below this the float32 squares cv2.magnitude makes lose precision (underflow), above it
# they overflow: bounds outside this range are not used to skip pixels
SMALLEST_BOUND, LARGEST_BOUND = 1e-10, 1e18


class ColorClassifier(Module):
    """Marks the pixels of one colour, from the chromaticities r and g and the intensity I
    (the outputs of ColorTransform with RGB->rgI). In the rg plane white is (1/3, 1/3). As
    in Ikaros 2, the hue ``color`` c points in the direction (sin c, cos c) of the plane
    (r - 1/3, g - 1/3), so a pixel's hue is atan2(r - 1/3, g - 1/3) in degrees: blue
    (r = g = 0) is 225, a red of r = 2/3, g = 0 is 135 and a pure red (r = 1) 117, a pure
    green 333 (the class file gives red 135, green 315, blue 225). A pixel is selected
    (OUTPUT 1, else 0) when its hue is within ± ``width`` degrees of ``color`` (the
    boundary included) and its saturation lies strictly between ``saturation_min`` and
    ``saturation_max``. The saturation is the distance from white, sqrt((r - 1/3)² +
    (g - 1/3)²) (0 for gray, up to 0.75; this measure is this module's reading, the
    reference does not give it). I is only checked for size: black pixels have
    r = g = 1/3 from ColorTransform, saturation 0. With ``compensation`` the image's mean
    chromaticity is moved to white first (a gray-world correction for the colour of the
    light; the Ikaros 2 class's compensation formula is not in the reference, this one is
    this module's). With ``diagnostics`` the COLORSPACE outputs show the rg plane as a
    colour image (r to the right, g up, 256 x 256): each chromaticity in its own colour at
    half brightness, the selected region at full brightness, and the chromaticities of the
    image's pixels in white (the Ikaros 2 class's drawing is not described; this one is
    this module's)."""

    compensation = Parameter(False, "move the image's mean chromaticity to white first")
    diagnostics = Parameter(True, "draw the COLORSPACE outputs")
    color = Parameter(225.0, "the hue to select, in degrees")
    width = Parameter(20.0, "how far the hue may lie from color, in degrees either side")
    saturation_min = Parameter(0.05, "the least saturation selected")
    saturation_max = Parameter(0.50, "the most saturation selected")
    R = Input("the chromaticity r = R / (R+G+B), (rows, cols)")
    G = Input("the chromaticity g = G / (R+G+B), (rows, cols)")
    I = Input("the intensity R+G+B, (rows, cols)")
    OUTPUT = Output("1 at the selected pixels, 0 elsewhere", shape="R.shape")
    COLORSPACE_R = Output("red plane of the rg-plane diagnostic image", shape="256, 256")
    COLORSPACE_G = Output("green plane of the rg-plane diagnostic image", shape="256, 256")
    COLORSPACE_B = Output("blue plane of the rg-plane diagnostic image", shape="256, 256")

    def configure(self):
        self.cv2 = opencv()

    def init(self):
        shapes = [getattr(self, n).shape for n in "RGI"]
        for name, shape in zip("RGI", shapes):
            check_gray(shape, name)
        if len(set(shapes)) > 1:
            raise ValueError(f"R, G and I must have the same size, not {shapes}")
        shape, pixels = shapes[0], int(np.prod(shapes[0]))
        self._dr, self._dg, self._magnitude = (np.zeros(shape, np.float32) for _ in range(3))
        self._candidates = np.zeros(shape, np.uint8)
        self._work = Selection(pixels, np.float32)
        g, r = np.mgrid[SIZE - 1:-1:-1, 0:SIZE] / (SIZE - 1.0)
        self._plane_valid = r + g <= 1.0
        self._plane_colour = np.stack([r, g, 1.0 - r - g]) * self._plane_valid
        self._plane_d = ((r - 1.0 / 3.0).ravel(), (g - 1.0 / 3.0).ravel())
        self._plane_work = Selection(SIZE * SIZE, np.float64)
        self._plane_key = None
        self._plane_base = np.zeros((3, SIZE, SIZE), np.float32)
        self._column, self._row = np.zeros(shape, np.float32), np.zeros(shape, np.float32)
        self._cell_index = np.zeros(pixels, np.intp)
        self._planes = (self.COLORSPACE_R, self.COLORSPACE_G, self.COLORSPACE_B)

    def _tests(self):
        """The parameters of the test as the arrays' arithmetic takes them."""
        hue = np.radians(self.color)
        width = np.radians(min(max(self.width, 0.0), 180.0))
        return (np.float32(np.sin(hue)), np.float32(np.cos(hue)), np.float32(np.cos(width)),
                self.saturation_min, self.saturation_max)

    def _select(self, dr: np.ndarray, dg: np.ndarray, work: "Selection",
                tests: tuple) -> np.ndarray:
        """Whether offsets (dr, dg) from white (1-D arrays) have the hue and saturation
        selected, as a view of a boolean buffer of ``work``. The hue test needs no angles:
        within ± width of the direction u = (sin c, cos c) means d · u >= |d| cos(width)
        (every hue when width is 180 or more). Computed in the arrays' own precision."""
        sin_c, cos_c, cos_width, low, high = tests
        n = len(dr)
        saturation, along, limit = (b[:n] for b in work.values)
        selected, test = work.selected[:n], work.test[:n]
        np.hypot(dr, dg, out=saturation)
        np.multiply(dr, sin_c, out=along)
        np.multiply(dg, cos_c, out=limit)
        np.add(along, limit, out=along)
        np.multiply(saturation, cos_width, out=limit)
        np.greater_equal(along, limit, out=selected)
        np.greater(saturation, low, out=test)
        selected &= test
        np.less(saturation, high, out=test)
        selected &= test
        return selected

    def tick(self):
        dr, dg = self._dr, self._dg
        np.subtract(self.R, 1.0 / 3.0, out=dr)
        np.subtract(self.G, 1.0 / 3.0, out=dg)
        if self.compensation:
            dr -= dr.mean()
            dg -= dg.mean()
        self._classify()
        if self.diagnostics:
            self._draw()

    def _classify(self):
        """OUTPUT from the offsets. The exact test (float32 hypot) runs only on the pixels
        whose saturation cv2.magnitude puts near or inside the bounds, or on every pixel
        when those are many."""
        tests = self._tests()
        low, high = np.float32(tests[3]), np.float32(tests[4])
        self.cv2.magnitude(self._dr, self._dg, magnitude=self._magnitude)
        self.cv2.inRange(self._magnitude,
                         float(low) * (1 - MARGIN) if low >= SMALLEST_BOUND else -np.inf,
                         float(high) * (1 + MARGIN) if high <= LARGEST_BOUND else np.inf,
                         dst=self._candidates)
        dr, dg, output = self._dr.reshape(-1), self._dg.reshape(-1), self.OUTPUT.reshape(-1)
        candidates = np.flatnonzero(self._candidates)
        if len(candidates) > len(output) // 4:
            np.copyto(output, self._select(dr, dg, self._work, tests))
            return
        work = self._work
        n = len(candidates)
        np.take(dr, candidates, out=work.dr[:n])
        np.take(dg, candidates, out=work.dg[:n])
        selected = self._select(work.dr[:n], work.dg[:n], work, tests)
        output.fill(0.0)
        output[candidates[selected]] = 1.0

    def _draw(self):
        """The rg plane in its colours, at full brightness where selected, and white where
        a pixel of the image lies (its chromaticity rounded to the plane's 256 steps)."""
        tests = self._tests()
        if tests != self._plane_key:
            self._plane_key = tests
            selected = self._select(*self._plane_d, self._plane_work, tests)
            brightness = np.where(selected.reshape(SIZE, SIZE) & self._plane_valid, 1.0, 0.5)
            np.multiply(self._plane_colour, brightness, out=self._plane_base)
        column, row = self._column, self._row
        np.add(self._dr, 1 / 3, out=column)
        np.subtract(2 / 3, self._dg, out=row)
        for steps in (column, row):
            np.multiply(steps, SIZE - 1, out=steps)
            np.rint(steps, out=steps)
            np.clip(steps, 0, SIZE - 1, out=steps)
        np.multiply(row, SIZE, out=row)             # whole numbers below 2^24: exact
        np.add(row, column, out=row)
        np.copyto(self._cell_index, row.reshape(-1), casting="unsafe")
        try:
            seen = np.bincount(self._cell_index, minlength=SIZE * SIZE) > 0
        except ValueError:
            raise ValueError("R or G is NaN: the diagnostic plane (diagnostics) can not show "
                             "it") from None
        for out, base in zip(self._planes, self._plane_base):
            np.copyto(out, base)
            out.reshape(-1)[seen] = 1.0


class Selection:
    """Work buffers of the test for up to ``size`` pixels, in one precision."""

    def __init__(self, size: int, dtype):
        self.values = [np.zeros(size, dtype) for _ in range(3)]
        self.dr, self.dg = np.zeros(size, dtype), np.zeros(size, dtype)
        self.selected, self.test = np.zeros(size, bool), np.zeros(size, bool)
