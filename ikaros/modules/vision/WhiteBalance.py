"""WhiteBalance: von Kries white balance on a reference region."""
import numpy as np

from ikaros.module import Parameter

from ._colour import ThreePlanes


class WhiteBalance(ThreePlanes):
    """Von Kries white balance: each of the red, green and blue planes is multiplied by the
    gain that brings its mean over a reference region to the target colour,
    gain = (target / 255) / mean. The reference region is the rectangle of columns
    ``x0``..``x1`` and rows ``y0``..``y1`` (pixels, both ends included, clipped to the
    image); by default the single pixel in column 10, row 20. The targets are 8-bit levels
    (255 is 1.0), as their Ikaros 2 defaults of 255 suggest. A plane whose region mean is 0
    keeps gain 1. The region and targets may change while the model runs. The image comes
    on INPUT (3, rows, cols) or on INPUT0..2, and goes out on OUTPUT and on OUTPUT0..2.
    (This reading of x0, x1, y0 and y1 as the region's bounds is this module's; the four
    further parameters of the Ikaros 2 class are not implemented.)"""

    red_target = Parameter(255.0, "the red level the region is brought to (0..255)")
    green_target = Parameter(255.0, "the green level the region is brought to (0..255)")
    blue_target = Parameter(255.0, "the blue level the region is brought to (0..255)")
    x0 = Parameter(10, "first column of the reference region")
    x1 = Parameter(10, "last column of the reference region")
    y0 = Parameter(20, "first row of the reference region")
    y1 = Parameter(20, "last row of the reference region")

    def compute(self):
        rows, cols = self.OUTPUT.shape[1:]
        r0, r1 = sorted((min(max(self.y0, 0), rows - 1), min(max(self.y1, 0), rows - 1)))
        c0, c1 = sorted((min(max(self.x0, 0), cols - 1), min(max(self.x1, 0), cols - 1)))
        targets = (self.red_target, self.green_target, self.blue_target)
        for plane, out, target in zip(self.planes_in, self.OUTPUT, targets):
            mean = float(plane[r0:r1 + 1, c0:c1 + 1].mean())
            gain = target / 255.0 / mean if mean != 0 else 1.0
            np.multiply(plane, gain, out=out)
