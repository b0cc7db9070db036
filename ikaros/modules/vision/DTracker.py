"""DTracker: follows an object through the images with a correlation filter."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import GrayImage, check_image, opencv

LEARNING_RATE = 0.125      # how fast the filter adapts to the object's changing look
SIGMA = 2.0                # width in pixels of the filter's desired response peak
LOST_PSR = 6.0             # a peak-to-sidelobe ratio below this means the object is lost


class DTracker(Module):
    """Follows one object from image to image with an adaptive correlation filter (MOSSE,
    Bolme et al. 2010), the family of dlib's correlation tracker that Ikaros 2 used (dlib's
    also adapts the box's scale; this one keeps the size of the box). The filter is learned
    on a window twice the size of the box, and each tick the peak of its correlation with
    the new image moves the box. Tracking starts at `box` (x0 y0 x1 y1 in 0..1) on the first
    tick, and again whenever the optional BOX input changes to a box of positive size (for
    example a face detector's bounds). A colour image is tracked on its intensity.
    TRACKER_BOUNDS are the tracked box's four corners (x, y) clockwise from the top-left and
    TRACKER_POSITION its centre, in 0..1 image coordinates. TRACKING is 0 when the
    correlation peak is weak (peak-to-sidelobe ratio below 6: the object is lost or hidden);
    the box then stays where it was and the filter does not learn until the peak is back."""

    box = Parameter("0.4 0.4 0.6 0.6", "the box tracked from the first tick: x0 y0 x1 y1 in "
                    "0..1", type="array")
    INPUT = Input("the image: gray (rows, cols) or colour (3, rows, cols)")
    BOX = Input("a box (x0, y0, x1, y1) in 0..1 to track from now on, when it changes",
                optional=True)
    TRACKER_BOUNDS = Output("the tracked box's corners (x, y), clockwise from the top-left, "
                            "in 0..1", size="8")
    TRACKER_POSITION = Output("the tracked box's centre (x, y) in 0..1", size="2")
    TRACKING = Output("1 while the object is tracked, 0 when it is lost", size="1")

    def configure(self):
        self.cv2 = opencv()

    def init(self):
        check_image(self.INPUT.shape)
        rows, cols = self.INPUT.shape[-2:]
        self._scale = np.array([cols, rows], np.float64)
        self._gray = GrayImage(self.INPUT)
        self._start = np.asarray(self.box, np.float64).ravel()
        if self._start.size != 4 or not (self._start[2] > self._start[0] and
                                         self._start[3] > self._start[1]):
            raise ValueError(f"box must be x0 y0 x1 y1 with x1 > x0 and y1 > y0, not "
                             f"{self.box!r}")
        self._filter = None
        self._last_box = None

    def _patch(self, gray):
        """The window around the box, preprocessed: log, zero mean, unit variance, Hann."""
        w, h = self._window_size
        patch = self.cv2.getRectSubPix(gray, (w, h), tuple(self._centre))
        patch = np.log1p(patch * 255.0)
        patch -= patch.mean()
        patch /= patch.std() + 1e-5
        return patch * self._hann

    def _begin(self, gray, box):
        x0, y0, x1, y1 = box * np.tile(self._scale, 2)
        self._box_size = np.array([x1 - x0, y1 - y0])
        self._centre = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
        w, h = (max(4, int(round(2 * s))) for s in self._box_size)
        self._window_size = (w, h)
        self._hann = self.cv2.createHanningWindow((w, h), self.cv2.CV_32F)
        yy, xx = np.mgrid[0:h, 0:w]
        goal = np.exp(-((xx - (w - 1) / 2) ** 2 + (yy - (h - 1) / 2) ** 2) / (2 * SIGMA ** 2))
        self._goal = np.fft.fft2(goal)
        patch = self._patch(gray)
        rng = np.random.default_rng(0)
        numerator = np.zeros((h, w), complex)
        denominator = np.zeros((h, w), complex)
        for k in range(8):                     # the patch and small random warps of it
            sample = patch if k == 0 else self._warp(patch, rng)
            f = np.fft.fft2(sample)
            numerator += self._goal * np.conj(f)
            denominator += f * np.conj(f)
        self._a, self._b = numerator, denominator + 1e-3
        self._filter = self._a / self._b
        self._publish(True)

    def _warp(self, patch, rng):
        h, w = patch.shape
        angle = rng.uniform(-0.1, 0.1)
        scale = 1 + rng.uniform(-0.05, 0.05)
        m = self.cv2.getRotationMatrix2D(((w - 1) / 2, (h - 1) / 2), np.degrees(angle), scale)
        return self.cv2.warpAffine(patch, m, (w, h), borderMode=self.cv2.BORDER_REFLECT)

    def _publish(self, tracking):
        (cx, cy), (w, h) = self._centre, self._box_size
        corners = np.array([[cx - w / 2, cy - h / 2], [cx + w / 2, cy - h / 2],
                            [cx + w / 2, cy + h / 2], [cx - w / 2, cy + h / 2]])
        self.TRACKER_BOUNDS[...] = (corners / self._scale).ravel()
        self.TRACKER_POSITION[...] = self._centre / self._scale
        self.TRACKING[0] = float(tracking)

    def _psr(self, response, peak):
        """Peak-to-sidelobe ratio: the peak against the response outside 11 x 11 around it."""
        y, x = peak
        side = response.copy()
        side[max(0, y - 5):y + 6, max(0, x - 5):x + 6] = np.nan
        return (response[y, x] - np.nanmean(side)) / (np.nanstd(side) + 1e-5)

    def tick(self):
        gray = self._gray()
        if self.BOX is not None:
            box = np.asarray(self.BOX, np.float64).ravel()[:4]
            if box[2] > box[0] and box[3] > box[1] and (
                    self._last_box is None or not np.array_equal(box, self._last_box)):
                self._last_box = box.copy()
                self._begin(gray, box)
                return
        if self._filter is None:
            self._begin(gray, self._start)
            return
        response = np.real(np.fft.ifft2(self._filter * np.fft.fft2(self._patch(gray))))
        peak = np.unravel_index(np.argmax(response), response.shape)
        if self._psr(response, peak) < LOST_PSR:
            self.TRACKING[0] = 0.0
            return
        w, h = self._window_size
        self._centre = self._centre + [peak[1] - (w - 1) / 2, peak[0] - (h - 1) / 2]
        f = np.fft.fft2(self._patch(gray))
        self._a = (1 - LEARNING_RATE) * self._a + LEARNING_RATE * self._goal * np.conj(f)
        self._b = (1 - LEARNING_RATE) * self._b + LEARNING_RATE * (f * np.conj(f) + 1e-3)
        self._filter = self._a / self._b
        self._publish(True)
