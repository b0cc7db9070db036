"""BlockMatching: optical flow at given points by block matching."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import GrayImage, check_image, opencv


class BlockMatching(Module):
    """Optical flow at the points in POINTS: the block of (2 · block_radius + 1)² pixels
    around each point in INPUT-LAST is looked for in INPUT within search_window_radius
    pixels in every direction (OpenCV's matchTemplate, a full search), and the best match
    gives the point's motion. Points are pixel coordinates (x = column, y = row). FLOW has
    one row (x, y, dx, dy) per point; a point whose block does not fit in the image, or a
    row beyond NO-OF-POINTS, gives 0 0 0 0. `metric` 0 is the sum of squared differences,
    1 the normalised correlation coefficient. `search_method` is read for compatibility: the
    search is always exhaustive. A colour image is matched on its intensity. DEBUG is the
    intensity of INPUT at 320 × 240 with the motion of each point drawn as a white line.
    (The reference gives Ikaros 2's interface and purpose, not its formulas, and no golden
    output reaches the class: the matching and the layout of FLOW are this project's
    reading. Ikaros 2's DirectionDetector, which reads FLOW, computes as if its rows were
    (x0, y0, x1, y1).)"""

    block_radius = Parameter(5, "the block is 2 · block_radius + 1 pixels square", type="int")
    search_window_radius = Parameter(32, "largest motion searched, in pixels, in each "
                                     "direction", type="int")
    search_method = Parameter(0, "compatibility only: the search is exhaustive", type="int")
    metric = Parameter(0, "0: sum of squared differences; 1: normalised correlation "
                       "coefficient", type="int")

    INPUT = Input("the image now: gray (rows, cols) or colour (3, rows, cols)")
    INPUT_LAST = Input("the earlier image (often INPUT through a delay-1 connection)",
                       name="INPUT-LAST")
    POINTS = Input("the points to follow, one row (x, y) per point, in pixels")
    NO_OF_POINTS = Input("how many rows of POINTS are used (default: all)", optional=True,
                         name="NO-OF-POINTS")
    FLOW = Output("one row (x, y, dx, dy) per point: where it was and how far it moved, in "
                  "pixels", name="FLOW")
    FLOW_SIZE = Output("the number of points matched", size="1", name="FLOW-SIZE")
    DEBUG = Output("the image (240 x 320) with the motions drawn", size_x="320",
                   size_y="240")

    def configure(self):
        self.cv2 = opencv()

    def set_sizes(self):
        shape = self.input_shape("POINTS")
        if shape is not None:
            n = int(np.prod(shape)) // 2
            if n < 1:
                raise ValueError(f"POINTS must hold (x, y) rows, not shape {shape}")
            self.set_output_shape("FLOW", (n, 4))

    def init(self):
        check_image(self.INPUT.shape)
        if self.INPUT_LAST.shape != self.INPUT.shape:
            raise ValueError(f"INPUT-LAST has shape {self.INPUT_LAST.shape}, INPUT "
                             f"{self.INPUT.shape}")
        self._now, self._last = GrayImage(self.INPUT), GrayImage(self.INPUT_LAST)
        self._points = self.POINTS.reshape(-1, 2)[:self.FLOW.shape[0]]
        self.FLOW.fill(0)

    def tick(self):
        cv2 = self.cv2
        now, last = self._now(), self._last()
        rows, cols = now.shape
        b, s = self.block_radius, self.search_window_radius
        n = len(self._points)
        if self.NO_OF_POINTS is not None:
            n = max(0, min(n, int(self.NO_OF_POINTS.flat[0])))
        method = cv2.TM_SQDIFF if self.metric == 0 else cv2.TM_CCOEFF_NORMED
        self.FLOW.fill(0)
        matched = 0
        for i, (x, y) in enumerate(np.rint(self._points[:n]).astype(int)):
            if not (b <= x < cols - b and b <= y < rows - b):
                continue
            block = last[y - b:y + b + 1, x - b:x + b + 1]
            top, left = max(0, y - b - s), max(0, x - b - s)
            region = now[top:min(rows, y + b + s + 1), left:min(cols, x + b + s + 1)]
            score = cv2.matchTemplate(region, block, method)
            low, high, low_at, high_at = cv2.minMaxLoc(score)
            mx, my = low_at if method == cv2.TM_SQDIFF else high_at
            self.FLOW[i] = (x, y, left + mx - (x - b), top + my - (y - b))
            matched += 1
        self.FLOW_SIZE[0] = matched
        self._draw(now, n)

    def _draw(self, now, n):
        cv2 = self.cv2
        rows, cols = now.shape
        cv2.resize(now, (320, 240), dst=self.DEBUG, interpolation=cv2.INTER_AREA)
        fx, fy = 320 / cols, 240 / rows
        for x, y, dx, dy in self.FLOW[:n]:
            cv2.line(self.DEBUG, (int(x * fx), int(y * fy)),
                     (int((x + dx) * fx), int((y + dy) * fy)), 1.0, 1)
