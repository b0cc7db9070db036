"""WhiteBalance: von Kries white balance on a reference region."""
import numpy as np

from ikaros.module import Parameter

from ._colour import ThreePlanes

# The defaults of the Ikaros 3 class (its golden outputs show them), used in a model file
# of that version for the parameters the module's element does not set.
IKAROS3_DEFAULTS = {"red_target": 1.0, "green_target": 1.0, "blue_target": 1.0,
                    "x0": 0, "x1": 1, "y0": 0, "y1": 1}


class WhiteBalance(ThreePlanes):
    """Von Kries white balance, as Ikaros 2 and 3 compute it: each of the red, green and
    blue planes is multiplied by gain = target / mean, where mean is the plane's mean over
    the reference region, the columns ``x0`` .. ``x1`` - 1 and rows ``y0`` .. ``y1`` - 1
    (pixels; x1 and y1 are exclusive, and the region is clipped to the image). The targets
    are in the image's own units (1 is white for images of 0..1). A plane whose region mean
    is 0 gets gain 0 (what Ikaros 3 gives; Ikaros 2's result is not documented). The
    defaults are Ikaros 2's (targets 255; x0 = x1 = 10 and y0 = y1 = 20, an empty region,
    so a model must set the region); in a model file of Ikaros 3 (``dialect`` 3) the
    parameters the module's element does not set take Ikaros 3's defaults instead: targets
    1 and the region x0 = 0, x1 = 1, y0 = 0, y1 = 1, the top-left pixel. An empty region is
    an error. The region and targets may change while the model runs. The image comes on
    INPUT (3, rows, cols) or on INPUT0..2, and goes out on OUTPUT and on OUTPUT0..2. (The
    four further parameters of the Ikaros 2 class are not described in the reference and
    are not implemented.)"""

    red_target = Parameter(255.0, "the red value the region's mean is brought to")
    green_target = Parameter(255.0, "the green value the region's mean is brought to")
    blue_target = Parameter(255.0, "the blue value the region's mean is brought to")
    x0 = Parameter(10, "first column of the reference region")
    x1 = Parameter(10, "the column after the reference region's last")
    y0 = Parameter(20, "first row of the reference region")
    y1 = Parameter(20, "the row after the reference region's last")

    def init(self):
        super().init()
        if self.dialect == "3":
            given = getattr(self.element, "attrs", {})
            for name, value in IKAROS3_DEFAULTS.items():
                if name not in given:
                    setattr(self, name, value)
        self._region()

    def _region(self) -> tuple[slice, slice]:
        """The rows and columns of the reference region, clipped to the image."""
        rows, cols = self.OUTPUT.shape[1:]
        r0, r1 = max(self.y0, 0), min(self.y1, rows)
        c0, c1 = max(self.x0, 0), min(self.x1, cols)
        if r1 <= r0 or c1 <= c0:
            raise ValueError(f"the reference region (columns x0={self.x0} to x1={self.x1}, "
                             f"rows y0={self.y0} to y1={self.y1}, ends excluded) has no "
                             f"pixel in the {rows} x {cols} image")
        return slice(r0, r1), slice(c0, c1)

    def compute(self):
        region = self._region()
        targets = (self.red_target, self.green_target, self.blue_target)
        for plane, out, target in zip(self.planes_in, self.OUTPUT, targets):
            mean = float(np.mean(plane[region], dtype=np.float64))
            np.multiply(plane, target / mean if mean != 0 else 0.0, out=out)
