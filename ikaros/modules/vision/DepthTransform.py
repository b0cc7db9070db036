"""DepthTransform: image positions with depths to homogeneous matrices in space."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter


POINT = 12          # values read per point: a 3 x 4 homogeneous matrix
WRITTEN = 16        # values written per point: a 4 x 4 homogeneous matrix


class DepthTransform(Module):
    """Turns points given as homogeneous matrices whose translation holds an image position
    and a depth into matrices whose translation is the point in the camera's frame (x
    forward, the depth; y to the left; z), as Ikaros 2 does (its golden outputs show each
    part of this). INPUT holds one point per row: a 3 x 4 matrix, 12 values, of which
    element 3 is the image x (column, in pixels of an x_res x y_res image), element 7 the
    image y (row) and element 11 the depth d. The result for the point is the matrix
    [[1, 0, 0, d], [0, 1, 0, d · (x_res/2 - x) / fx], [0, 0, 1, d · (y - y_res/2) / fy],
    [0, 0, 0, 1]], with fx = (x_res/2) / tan(fov_h/2) and fy = (y_res/2) / tan(fov_v/2),
    written as 16 values from the start of the output row of the point; OUTPUT has the
    shape of INPUT and is 0 elsewhere. Rows of 12 values therefore give rows of 3 x 4
    matrices (the fourth row of each 4 x 4 matrix is overwritten by the next point, and the
    last one's is dropped). The original does the same for rows of any width: it converts
    INPUT.size // 12 points, reads each point's 12 values from the start of its row on in
    memory order (into the following rows when a row is shorter), and writes its 16 values
    from the start of its output row on, so later points overwrite earlier ones; this
    module does the same, with a warning when the rows are not 12 wide (the result is then
    meaningless), and drops what would fall past the end of OUTPUT."""

    x_res = Parameter(640, "columns of the depth image", type="int")
    y_res = Parameter(480, "rows of the depth image", type="int")
    fov_h = Parameter(1.1, "horizontal field of view, radians")
    fov_v = Parameter(1.1, "vertical field of view, radians")
    INPUT = Input("points, one 3 x 4 matrix (12 values) per row: x at 3, y at 7, depth at 11")
    OUTPUT = Output("the points in space, the same layout (3 x 4 matrices)", size_set="INPUT")

    def init(self):
        flat = self.INPUT.reshape(-1)
        width = self.INPUT.shape[-1] if self.INPUT.ndim else 1
        count = flat.size // POINT
        if count and width != POINT:
            self.warning(f"INPUT rows are {width} wide, not {POINT} (a 3 x 4 matrix): the "
                      f"original reads and writes them as 12-value points all the same")
        self._read = np.arange(count)[:, None] * width + np.array([3, 7, 11])
        # each output position holds the value of the last point that writes it
        end = min(flat.size, (count - 1) * width + WRITTEN) if count else 0
        position = np.arange(end)
        point = np.minimum(position // width, count - 1)
        entry = position - point * width
        kept = entry < WRITTEN
        self._written, self._from = position[kept], (point[kept], entry[kept])
        self._matrices = np.zeros((count, WRITTEN), np.float64)
        self._matrices[:, [0, 5, 10, 15]] = 1.0

    def tick(self):
        flat = self.OUTPUT.reshape(-1)
        flat.fill(0.0)
        if not len(self._matrices):
            return
        x, y, depth = (self.INPUT.reshape(-1)[self._read].astype(np.float64)).T
        fx = (self.x_res / 2) / math.tan(self.fov_h / 2)
        fy = (self.y_res / 2) / math.tan(self.fov_v / 2)
        m = self._matrices
        m[:, 3] = depth
        m[:, 7] = depth * (self.x_res / 2 - x) / fx
        m[:, 11] = depth * (y - self.y_res / 2) / fy
        flat[self._written] = m[self._from]
