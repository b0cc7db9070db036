"""WhiteBalance: von Kries white balance on a reference region."""
import numpy as np

from ikaros.module import Parameter

from ._colour import ThreePlanes


class WhiteBalance(ThreePlanes):
    """Von Kries white balance, as Ikaros 2 and 3 compute it: each of the red, green and
    blue planes is multiplied by gain = target / mean, where mean is the plane's mean over
    the reference region, the columns ``x0`` .. ``x1`` - 1 and rows ``y0`` .. ``y1`` - 1
    (pixels; x1 and y1 are exclusive, and the region is clipped to the image). The targets
    are in the image's own units (1 is white for images of 0..1). A region with no pixel has
    no mean: the output is NaN, as Ikaros 2 gives it (its golden outputs, with its default
    region), with a warning (Ikaros 3's result for it is not known; this module gives the
    same). A plane whose region mean is 0 gets gain 0 (what Ikaros 3 gives; Ikaros 2's
    result is not known and this module gives the same). The defaults are Ikaros 2's
    (targets 255; x0 = x1 = 10 and y0 = y1 = 20, an empty region, so a model must set the
    region); in a model file of Ikaros 3 (``dialect`` 3) the parameters the module's
    element does not set take Ikaros 3's defaults instead: targets 1 and the region x0 = 0,
    x1 = 1, y0 = 0, y1 = 1, the top-left pixel. The region and targets may change while the
    model runs. The image comes on INPUT (3, rows, cols) or on INPUT0..2 (a vector is a
    one-row plane), and goes out on OUTPUT and on OUTPUT0..2.

    ``log_x0`` .. ``log_y1`` (in both versions' interfaces, default 0: off) name a second
    region the same way; when it has pixels, the module prints the mean red, green and blue
    of that region before and after the balance on every tick. Only their names and
    defaults are known, so what they do is this project's reading: a region whose colour is
    logged."""

    # Ikaros 3's defaults (default_v3) are those its golden outputs show
    red_target = Parameter(255.0, "the red value the region's mean is brought to",
                           default_v3=1.0)
    green_target = Parameter(255.0, "the green value the region's mean is brought to",
                             default_v3=1.0)
    blue_target = Parameter(255.0, "the blue value the region's mean is brought to",
                            default_v3=1.0)
    x0 = Parameter(10, "first column of the reference region", default_v3=0)
    x1 = Parameter(10, "the column after the reference region's last", default_v3=1)
    y0 = Parameter(20, "first row of the reference region", default_v3=0)
    y1 = Parameter(20, "the row after the reference region's last", default_v3=1)
    log_x0 = Parameter(0, "first column of the region whose colour is printed")
    log_x1 = Parameter(0, "the column after its last (log_x1 = log_x0: no logging)")
    log_y0 = Parameter(0, "first row of the region whose colour is printed")
    log_y1 = Parameter(0, "the row after its last")

    def init(self):
        super().init()
        if self._region(self.x0, self.x1, self.y0, self.y1) is None:
            rows, cols = self.OUTPUT.shape[1:]
            self.warning(f"the reference region (columns x0={self.x0} to x1={self.x1}, "
                      f"rows y0={self.y0} to y1={self.y1}, ends excluded) has no pixel in "
                      f"the {rows} x {cols} image: the output is NaN, as in the original")

    def _region(self, x0, x1, y0, y1) -> tuple[slice, slice] | None:
        """The rows and columns of a region clipped to the image; None when it is empty."""
        rows, cols = self.OUTPUT.shape[1:]
        r0, r1 = max(int(y0), 0), min(int(y1), rows)
        c0, c1 = max(int(x0), 0), min(int(x1), cols)
        return (slice(r0, r1), slice(c0, c1)) if r1 > r0 and c1 > c0 else None

    def tick(self):
        region = self._region(self.x0, self.x1, self.y0, self.y1)
        targets = (self.red_target, self.green_target, self.blue_target)
        for plane, out, target in zip(self.planes_in, self.OUTPUT, targets):
            if region is None:
                out.fill(np.nan)
                continue
            mean = float(np.mean(plane[region], dtype=np.float64))
            np.multiply(plane, target / mean if mean != 0 else 0.0, out=out)
        logged = self._region(self.log_x0, self.log_x1, self.log_y0, self.log_y1)
        if logged is not None:
            before = [float(np.mean(p[logged], dtype=np.float64)) for p in self.planes_in]
            after = [float(np.mean(p[logged], dtype=np.float64)) for p in self.OUTPUT]
            self.print(f"log region RGB {' '.join(f'{v:.6g}' for v in before)} -> "
                       f"{' '.join(f'{v:.6g}' for v in after)}")
