"""ColorClassifier: pixels of one hue in rg chromaticity."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import check_gray, opencv

SIZE = 256


class ColorClassifier(Module):
    """Marks the pixels of one colour, from the chromaticities r and g and the intensity I
    (the outputs of ColorTransform with RGB->rgI). In the rg plane white is (1/3, 1/3);
    a pixel's hue is the direction from white to (r, g), in degrees counter-clockwise
    from the r axis (red is about 333, green 117, blue 225), and its saturation the
    distance from white (0 for gray, up to 0.75). OUTPUT is 1 where the hue lies in a
    sector ``width`` degrees wide centred on ``color`` and the saturation lies between
    ``saturation_min`` and ``saturation_max``, and 0 elsewhere (tested without angles: the
    offset d from white is in the sector when d · u >= |d| cos(width / 2), u pointing at
    ``color``; gray itself, with no hue, counts as in every sector). I is only checked for size:
    black pixels have r = g = 0 (saturation 0.47, hue 225) and are best removed by
    ``saturation_max`` or a mask. With ``compensation`` the image's mean chromaticity is
    moved to white first (a gray-world correction for the colour of the light). With
    ``diagnostics`` the COLORSPACE outputs show the rg plane as a colour image (r to the
    right, g up, 256 x 256): each chromaticity in its own colour at half brightness, the
    selected region at full brightness, and the chromaticities of the image's pixels in
    white. (The Ikaros 2 class's exact hue and compensation formulas are not known; these
    are stated here.)"""

    compensation = Parameter(False, "move the image's mean chromaticity to white first")
    diagnostics = Parameter(True, "draw the COLORSPACE outputs")
    color = Parameter(225.0, "the hue to select, in degrees")
    width = Parameter(20.0, "the width of the selected hue sector, in degrees")
    saturation_min = Parameter(0.05, "the least saturation selected")
    saturation_max = Parameter(0.50, "the most saturation selected")
    R = Input("the chromaticity r = R / (R+G+B), (rows, cols)")
    G = Input("the chromaticity g = G / (R+G+B), (rows, cols)")
    I = Input("the intensity (R+G+B) / 3, (rows, cols)")
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
        shape = self.R.shape
        self._dr, self._dg = np.zeros(shape, np.float32), np.zeros(shape, np.float32)
        self._sat, self._along = np.zeros(shape, np.float32), np.zeros(shape, np.float32)
        self._limit = np.zeros(shape, np.float32)
        self._in_range, self._in_sector = np.zeros(shape, np.uint8), np.zeros(shape, np.uint8)
        g, r = np.mgrid[SIZE - 1:-1:-1, 0:SIZE] / (SIZE - 1.0)
        self._plane_valid = r + g <= 1.0
        self._plane_colour = np.stack([r, g, 1.0 - r - g]) * self._plane_valid
        self._plane_d = (r - 1.0 / 3.0, g - 1.0 / 3.0)
        self._planes = (self.COLORSPACE_R, self.COLORSPACE_G, self.COLORSPACE_B)

    def _sector(self):
        """The unit vector of the hue ``color`` and the cosine of half the width: a
        chromaticity offset d is in the sector when d · u >= |d| cos(width / 2)."""
        hue = np.radians(self.color)
        half = np.radians(min(max(self.width, 0.0), 360.0) / 2.0)
        return np.cos(hue), np.sin(hue), np.cos(half)

    def tick(self):
        cv2 = self.cv2
        dr, dg, sat, along = self._dr, self._dg, self._sat, self._along
        np.subtract(self.R, 1.0 / 3.0, out=dr)
        np.subtract(self.G, 1.0 / 3.0, out=dg)
        if self.compensation:
            dr -= dr.mean()
            dg -= dg.mean()
        ux, uy, cos_half = self._sector()
        cv2.magnitude(dr, dg, magnitude=sat)
        cv2.addWeighted(dr, ux, dg, uy, 0.0, dst=along)
        cv2.inRange(sat, self.saturation_min, self.saturation_max, dst=self._in_range)
        np.multiply(sat, cos_half, out=self._limit)
        cv2.compare(along, self._limit, cv2.CMP_GE, dst=self._in_sector)
        cv2.bitwise_and(self._in_range, self._in_sector, dst=self._in_sector)
        np.multiply(self._in_sector, 1.0 / 255.0, out=self.OUTPUT, casting="unsafe")
        if self.diagnostics:
            self._draw(dr, dg)

    def _draw(self, dr, dg):
        ux, uy, cos_half = self._sector()
        pr, pg = self._plane_d
        sat = np.hypot(pr, pg)
        selected = ((pr * ux + pg * uy >= sat * cos_half) & (sat >= self.saturation_min) &
                    (sat <= self.saturation_max) & self._plane_valid)
        brightness = np.where(selected, 1.0, 0.5)
        cols = np.clip(np.rint((dr + 1 / 3) * (SIZE - 1)), 0, SIZE - 1).astype(np.intp)
        rows = np.clip(np.rint((2 / 3 - dg) * (SIZE - 1)), 0, SIZE - 1).astype(np.intp)
        for out, colour in zip(self._planes, self._plane_colour):
            np.multiply(colour, brightness, out=out)
            out[rows, cols] = 1.0
