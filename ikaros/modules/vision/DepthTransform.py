"""DepthTransform: image positions with depths to points in space."""
from ikaros.module import Input, Module, Output, Parameter

from ._depth import to_points


class DepthTransform(Module):
    """Turns rows (x, y, depth) — an image position in pixels of an x_res × y_res depth
    image and its depth — into points (forward, left, up) in the camera's frame (the Ikaros
    frame: x forward, y left, z up), in the unit of the depth. Pixel (x, y) looks along the
    angles ((x + 0.5) / x_res - 0.5) · fov_h to the right and (0.5 - (y + 0.5) / y_res) ·
    fov_v up. Columns after the third are copied unchanged."""

    x_res = Parameter(640, "columns of the depth image", type="int")
    y_res = Parameter(480, "rows of the depth image", type="int")
    fov_h = Parameter(1.1, "horizontal field of view, radians")
    fov_v = Parameter(1.1, "vertical field of view, radians")
    INPUT = Input("rows (x, y, depth, ...)")
    OUTPUT = Output("rows (forward, left, up, ...)", size_set="INPUT")

    def init(self):
        if self.INPUT.shape[-1] < 3:
            raise ValueError(f"INPUT must have rows (x, y, depth), not shape "
                             f"{self.INPUT.shape}")

    def tick(self):
        x, y, d = self.INPUT[..., 0], self.INPUT[..., 1], self.INPUT[..., 2]
        self.OUTPUT[...] = self.INPUT
        forward, left, up = to_points(x, y, d, self.x_res, self.y_res, self.fov_h, self.fov_v)
        self.OUTPUT[..., 0], self.OUTPUT[..., 1], self.OUTPUT[..., 2] = forward, left, up
