"""ColorClassifier: pixels of one hue in rg chromaticity."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import check_gray

SIZE = 256


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

    def init(self):
        shapes = [getattr(self, n).shape for n in "RGI"]
        for name, shape in zip("RGI", shapes):
            check_gray(shape, name)
        if len(set(shapes)) > 1:
            raise ValueError(f"R, G and I must have the same size, not {shapes}")
        g, r = np.mgrid[SIZE - 1:-1:-1, 0:SIZE] / (SIZE - 1.0)
        self._plane_valid = r + g <= 1.0
        self._plane_colour = np.stack([r, g, 1.0 - r - g]) * self._plane_valid
        self._plane_d = (r - 1.0 / 3.0, g - 1.0 / 3.0)
        self._planes = (self.COLORSPACE_R, self.COLORSPACE_G, self.COLORSPACE_B)

    def _selected(self, dr: np.ndarray, dg: np.ndarray) -> np.ndarray:
        """Whether offsets (dr, dg) from white have the hue and saturation selected. The
        hue test needs no angles: within ± width of the direction u = (sin c, cos c) means
        d · u >= |d| cos(width) (every hue when width is 180 or more)."""
        saturation = np.hypot(dr, dg)
        hue = np.radians(self.color)
        along = dr * np.float32(np.sin(hue)) + dg * np.float32(np.cos(hue))
        width = np.radians(min(max(self.width, 0.0), 180.0))
        return ((along >= saturation * np.float32(np.cos(width))) &
                (saturation > self.saturation_min) & (saturation < self.saturation_max))

    def tick(self):
        dr = self.R - 1.0 / 3.0
        dg = self.G - 1.0 / 3.0
        if self.compensation:
            dr -= dr.mean()
            dg -= dg.mean()
        np.copyto(self.OUTPUT, self._selected(dr, dg))
        if self.diagnostics:
            self._draw(dr, dg)

    def _draw(self, dr, dg):
        selected = self._selected(*self._plane_d) & self._plane_valid
        brightness = np.where(selected, 1.0, 0.5)
        cols = np.clip(np.rint((dr + 1 / 3) * (SIZE - 1)), 0, SIZE - 1).astype(np.intp)
        rows = np.clip(np.rint((2 / 3 - dg) * (SIZE - 1)), 0, SIZE - 1).astype(np.intp)
        for out, colour in zip(self._planes, self._plane_colour):
            np.multiply(colour, brightness, out=out)
            out[rows, cols] = 1.0
