"""PointsToSalience: a salience map with a Gaussian bump at each point."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class PointsToSalience(Module):
    """A salience map of ``size_y`` rows and ``size_x`` columns with a Gaussian bump of
    height 1 at each point of POINTS (rows (x, y) in 0..1 of the map's width and height,
    docs/images.md, such as a face detector's centres). The bump of point i at the map
    element (r, c), whose centre is at u = (c + 0.5) / size_x, v = (r + 0.5) / size_y, is
    exp(-((u - x_i)² + (v - y_i)²) / (2 s_i²)), with s_i = ``standard_deviation`` (a fraction
    of the map's width and height) times WIDTHS[i] when WIDTHS is connected (a face's width,
    so a larger face gives a wider bump), else ``standard_deviation``. Bumps that overlap
    add. Rows whose x and y are both 0, or whose width is 0, are unused rows of a fixed-size
    list and give no bump. The original's class is known only by its interface: the formula
    is this project's reading."""

    size_x = Parameter(64, "the columns of the map", type="int", range=(1, None))
    size_y = Parameter(64, "the rows of the map", type="int", range=(1, None))
    standard_deviation = Parameter(0.2, "the width of a bump, as a fraction of the map",
                                   range=(0, None))

    POINTS = Input("the points, one row (x, y) each, in 0..1")
    WIDTHS = Input("a width per point that scales its bump", optional=True)
    OUTPUT = Output("the salience map", shape="@size_y, @size_x")

    def init(self):
        shape = tuple(self.input_shape("POINTS"))
        if not (shape[-1:] == (2,) or (len(shape) == 1 and shape[0] % 2 == 0)):
            raise ValueError(f"POINTS must have rows (x, y), not shape {shape}")

    def tick(self):
        points = np.asarray(self.POINTS, np.float64)
        points = points.reshape(-1, 2) if points.size else np.zeros((0, 2))
        sigma = np.full(len(points), float(self.standard_deviation))
        if self.WIDTHS is not None:
            widths = np.asarray(self.WIDTHS, np.float64).ravel()[:len(points)]
            points = points[:len(widths)]
            sigma = sigma[:len(widths)] * widths
        used = np.any(points != 0, axis=1) & (sigma > 0)
        points, sigma = points[used], sigma[used]
        u = (np.arange(self.size_x) + 0.5) / self.size_x
        v = (np.arange(self.size_y) + 0.5) / self.size_y
        k = -0.5 / sigma ** 2
        across = np.exp(k[:, None] * (u[None, :] - points[:, :1]) ** 2)
        down = np.exp(k[:, None] * (v[None, :] - points[:, 1:]) ** 2)
        self.OUTPUT[...] = down.T @ across
