"""DepthPointList: an RGB-D image as a list of coloured points."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._depth import pixel_angles


class DepthPointList(Module):
    """Turns an RGB-D image into one row per pixel, in row-major order: the 4 × 4
    homogeneous matrix (16 values, row by row) that places a point at the pixel's position
    in the camera's frame (the Ikaros frame: x forward, y left, z up; in the unit of DEPTH,
    e.g. mm), followed by the pixel's red, green and blue. Pixel (row r, column c) looks
    along the angles ((c + 0.5) / cols - 0.5) · fov_h to the right and
    (0.5 - (r + 0.5) / rows) · fov_v up. A pixel without a depth reading (0) gives a point
    at the camera. (The reference gives Ikaros 2's output size, 19 × 307200 for a 640 × 480
    image, and purpose; no golden output reaches the class, so the angles and the order of
    the values are this project's reading. Ikaros 2's DepthTransform places points by a
    pinhole model instead, its golden outputs show: (x_res/2 - x) / f with f = (x_res/2) /
    tan(fov_h/2).)"""

    fov_h = Parameter(1.1, "horizontal field of view, radians")
    fov_v = Parameter(1.1, "vertical field of view, radians")
    RED = Input("the red plane (rows, cols)")
    GREEN = Input("the green plane (rows, cols)")
    BLUE = Input("the blue plane (rows, cols)")
    DEPTH = Input("the depth image (rows, cols)")
    OUTPUT = Output("one row of 19 values per pixel: a 4 x 4 matrix and red, green, blue")

    def set_sizes(self):
        shape = self.input_shape("DEPTH")
        if shape is not None:
            self.set_output_shape("OUTPUT", (int(np.prod(shape)), 19))

    def init(self):
        shape = self.DEPTH.shape
        for name in ("RED", "GREEN", "BLUE"):
            if getattr(self, name).shape != shape:
                raise ValueError(f"{name} has shape {getattr(self, name).shape}, DEPTH "
                                 f"{shape}")
        rows, cols = shape
        self._right, self._up = pixel_angles(rows, cols, self.fov_h, self.fov_v)
        rows_view = self.OUTPUT.reshape(rows, cols, 19)
        self._view = rows_view
        identity = np.eye(4, dtype=np.float32).ravel()
        self.OUTPUT[:, :16] = identity

    def tick(self):
        v, d = self._view, self.DEPTH
        v[..., 3] = d
        np.multiply(d, -self._right, out=v[..., 7])
        np.multiply(d, self._up, out=v[..., 11])
        v[..., 16], v[..., 17], v[..., 18] = self.RED, self.GREEN, self.BLUE
