"""FASTDetector: FAST corners on OpenCV."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import GrayImage, Uint8Image, check_image, opencv

# (row, col) offsets of the 16 pixels on the circle of radius 3 around a candidate
CIRCLE = np.array([(-3, 0), (-3, 1), (-2, 2), (-1, 3), (0, 3), (1, 3), (2, 2), (3, 1),
                   (3, 0), (3, -1), (2, -2), (1, -3), (0, -3), (-1, -3), (-2, -2), (-3, -1)])


class FASTDetector(Module):
    """FAST corner detection on the gray image (the intensity of a colour one) in 8-bit
    levels: a corner is a pixel with 9 contiguous pixels on the 16-pixel circle of radius 3
    around it all brighter, or all darker, than it by more than ``threshold`` levels
    (OpenCV's FastFeatureDetector finds these). Each corner is scored by the sum of
    absolute differences on its circle beyond the threshold (the larger of the bright and
    the dark sums, as in the original FAST), and only corners with the highest score in
    their 3 x 3 neighbourhood are kept. OUTPUT is 1 at the corners, POINTS lists them as
    (x, y) = (column, row), best first, and POINT_COUNT says how many are listed (at most
    ``max_points``; the rest of POINTS is 0). Ikaros 2 bundled the original FAST code; the
    scoring and suppression are done here because OpenCV 5.0's own suppression returns no
    corners."""

    threshold = Parameter(40, "how much brighter or darker (0..255 levels) the circle must be")
    max_points = Parameter(5000, "the most corners listed")
    INPUT = Input("the image: gray (rows, cols), or colour (3, rows, cols) whose intensity "
                  "is used")
    OUTPUT = Output("1 at the corners, 0 elsewhere (rows, cols)")
    POINTS = Output("one row per corner: x (column), y (row)", shape="@max_points, 2")
    POINT_COUNT = Output("the number of corners listed", shape="1")

    def configure(self):
        self.cv2 = opencv()

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape:
            check_image(shape)
            self.set_output_shape("OUTPUT", shape[-2:])

    def init(self):
        self._gray = GrayImage(self.INPUT)
        self._levels = Uint8Image(self.OUTPUT.shape)
        self._scores = np.zeros(self.OUTPUT.shape, np.float32)
        self._best = np.zeros(self.OUTPUT.shape, np.float32)
        self._detector = self.cv2.FastFeatureDetector_create(int(self.threshold), False)

    def tick(self):
        cv2 = self.cv2
        levels = self._levels(self._gray())
        self._detector.setThreshold(int(self.threshold))
        found = self._detector.detect(levels)
        cols, rows = (np.rint(cv2.KeyPoint_convert(found)).astype(np.intp).reshape(-1, 2).T
                      if found else (np.zeros(0, np.intp), np.zeros(0, np.intp)))
        centre = levels[rows, cols].astype(np.int32)[:, None]
        ring = levels[rows[:, None] + CIRCLE[:, 0], cols[:, None] + CIRCLE[:, 1]]
        diff = ring.astype(np.int32) - centre
        t = int(self.threshold)
        bright = np.where(diff > t, diff - t, 0).sum(axis=1)
        dark = np.where(diff < -t, -diff - t, 0).sum(axis=1)
        score = np.maximum(bright, dark).astype(np.float32) + 1.0
        self._scores.fill(0.0)
        self._scores[rows, cols] = score
        cv2.dilate(self._scores, np.ones((3, 3), np.uint8), dst=self._best)
        keep = self._scores[rows, cols] == self._best[rows, cols]
        order = np.argsort(-score[keep], kind="stable")[:self.POINTS.shape[0]]
        rows, cols = rows[keep][order], cols[keep][order]
        n = rows.size
        self.POINTS[n:] = 0.0
        self.POINTS[:n, 0], self.POINTS[:n, 1] = cols, rows
        self.OUTPUT.fill(0.0)
        self.OUTPUT[rows, cols] = 1.0
        self.POINT_COUNT[0] = n
