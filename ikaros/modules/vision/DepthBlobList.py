"""DepthBlobList: objects standing in a depth image, found on a map seen from above."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import opencv
from ._depth import pixel_angles

GRID = 100
MAX_BLOBS = 10


class DepthBlobList(Module):
    """Finds objects in a depth image (in mm) on a 100 × 100 map of the floor seen from
    above. Every pixel with a depth becomes a point in the camera's frame (x forward, y
    left, z up; each pixel looks along the angles DepthPointList gives it), turned by `tilt`
    (up) and `pan` (left), in degrees, and placed by the camera pose POSITION (a 4 × 4
    matrix, 16 values; the camera at the origin when it is not connected). GRID is 1 for the
    cells of `range` / 100 mm that hold at least `min_points` points: row 0 is the far edge
    (x = range) and column 0 the left edge (y = range / 2) of a square of side `range` in
    front of the origin. BACKGROUND is the GRID of the first tick (and of the tick after the
    command "reset"), DILATED_BACKGROUND it grown by one cell, DETECTION the cells of GRID
    outside it and SMOOTHED that blurred by a Gaussian of one cell. Up to 10 local maxima of
    SMOOTHED above 0.2, more than two cells apart, are the objects: MAXIMA has their (x, y)
    in mm, and OUTPUT one row per object: a 4 × 4 matrix (16 values, row by row) that places
    it on the floor, and its strength (the maximum's value); rows past the last object are
    0. (What Ikaros 2 did in detail is not known; this is a plain background-subtraction
    blob finder.)"""

    pan = Parameter(0.0, "the camera's pan to the left, degrees")
    tilt = Parameter(0.0, "the camera's tilt upwards, degrees")
    range = Parameter(5000.0, "side of the square mapped, mm")
    min_points = Parameter(5, "points a cell needs to be occupied", type="int")
    fov_h = Parameter(1.1, "horizontal field of view, radians")
    fov_v = Parameter(1.1, "vertical field of view, radians")
    INPUT = Input("the depth image (rows, cols), mm; 0 for no reading")
    POSITION = Input("the camera's pose in the world, a 4 x 4 matrix", optional=True)
    GRID = Output("occupied cells of the map", shape="100, 100")
    BACKGROUND = Output("the map of the first tick", shape="100, 100")
    DILATED_BACKGROUND = Output("the background grown by one cell", shape="100, 100")
    DETECTION = Output("occupied cells outside the background", shape="100, 100")
    SMOOTHED = Output("the detection blurred", shape="100, 100")
    MAXIMA = Output("(x, y) in mm of each object", shape="10, 2")
    OUTPUT = Output("one row per object: a 4 x 4 matrix and the strength", shape="10, 17")

    def configure(self):
        self.cv2 = opencv()

    def init(self):
        if self.INPUT.ndim != 2:
            raise ValueError(f"INPUT must be a depth image (rows, cols), not shape "
                             f"{self.INPUT.shape}")
        rows, cols = self.INPUT.shape
        self._right, self._up = pixel_angles(rows, cols, self.fov_h, self.fov_v)
        self._learn = True
        self._counts = np.zeros((GRID, GRID), np.float32)

    def command(self, name, x=0, y=0, value=None):
        if name == "reset":
            self._learn = True

    def _pose(self):
        p, t = np.radians(self.pan), np.radians(self.tilt)
        pan = np.array([[np.cos(p), -np.sin(p), 0], [np.sin(p), np.cos(p), 0], [0, 0, 1]])
        tilt = np.array([[np.cos(t), 0, -np.sin(t)], [0, 1, 0], [np.sin(t), 0, np.cos(t)]])
        pose = np.eye(4)
        pose[:3, :3] = pan @ tilt
        if self.POSITION is not None:
            pose = np.asarray(self.POSITION, np.float64).reshape(4, 4) @ pose
        return pose

    def tick(self):
        cv2 = self.cv2
        d = self.INPUT
        valid = d > 0
        depth = d[valid]
        right = np.broadcast_to(self._right, d.shape)[valid]
        up = np.broadcast_to(self._up, d.shape)[valid]
        camera = np.stack([depth, -depth * right, depth * up, np.ones_like(depth)])
        world = (self._pose() @ camera)[:2]
        cell = self.range / GRID
        row = np.floor((self.range - world[0]) / cell).astype(np.int64)
        col = np.floor((self.range / 2 - world[1]) / cell).astype(np.int64)
        inside = (row >= 0) & (row < GRID) & (col >= 0) & (col < GRID)
        counts = np.bincount(row[inside] * GRID + col[inside], minlength=GRID * GRID)
        np.greater_equal(counts.reshape(GRID, GRID), self.min_points, out=self.GRID,
                         casting="unsafe")
        if self._learn:
            self._learn = False
            self.BACKGROUND[...] = self.GRID
            cv2.dilate(self.BACKGROUND, np.ones((3, 3), np.uint8), dst=self.DILATED_BACKGROUND)
        np.multiply(self.GRID, 1 - self.DILATED_BACKGROUND, out=self.DETECTION)
        cv2.GaussianBlur(self.DETECTION, (0, 0), 1.0, dst=self.SMOOTHED)
        peaks = (self.SMOOTHED == cv2.dilate(self.SMOOTHED, np.ones((3, 3), np.uint8))) & (
            self.SMOOTHED > 0.2)
        rows, cols = np.nonzero(peaks)
        order = np.argsort(-self.SMOOTHED[rows, cols], kind="stable")
        kept = []                  # a plateau gives several equal maxima: keep one of them
        for r, c in zip(rows[order], cols[order]):
            if all(abs(r - kr) > 2 or abs(c - kc) > 2 for kr, kc in kept):
                kept.append((r, c))
            if len(kept) == MAX_BLOBS:
                break
        self.MAXIMA.fill(0)
        self.OUTPUT.fill(0)
        for i, (r, c) in enumerate(kept):
            x, y = self.range - (r + 0.5) * cell, self.range / 2 - (c + 0.5) * cell
            self.MAXIMA[i] = (x, y)
            place = np.eye(4, dtype=np.float32)
            place[0, 3], place[1, 3] = x, y
            self.OUTPUT[i, :16] = place.ravel()
            self.OUTPUT[i, 16] = self.SMOOTHED[r, c]
