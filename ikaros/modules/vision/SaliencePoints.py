"""SaliencePoints: a saliency map from a list of points."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class SaliencePoints(Module):
    """Turns a list of points into a saliency map of ``size_x`` x ``size_y``: each point
    adds a Gaussian blob of standard deviation ``sigma`` pixels whose height is ``scale``
    times its salience, as the reference describes Ikaros 2's class (no golden output
    reaches it). INPUT has one point per row (a single row may be
    given as a vector); columns ``select`` and ``select`` + 1 hold x and y, positions in
    fractions of the map's width and height (docs/images.md: x from 0 at the left edge to
    1 at the right, y from 0 at the top to 1 at the bottom), so a point sits at
    (x·size_x, y·size_y) pixels from the top-left corner; column ``select_salience`` holds
    its salience ("none": every point has salience 1). The blob's value at a pixel is
    measured from the pixel's centre, (c + 0.5, r + 0.5), the library's convention (the
    reference does not say which point of a pixel Ikaros 2 uses, nor whether overlapping
    blobs add: here they add). COUNT (its first value), when connected, says how many rows
    are used. The blobs are added as one matrix product, not pixel by pixel."""

    size_x = Parameter(128, "width of the map")
    size_y = Parameter(128, "height of the map")
    sigma = Parameter(2.0, "standard deviation of each blob, in pixels")
    scale = Parameter(1.0, "the height of a blob of salience 1")
    select = Parameter(0, "the column of x (y is the next one)")
    select_salience = Parameter("none", "the column of the salience, or none for 1",
                                type="string")
    INPUT = Input("the points, one row each")
    COUNT = Input("how many rows of INPUT are used", optional=True)
    OUTPUT = Output("the saliency map", size_param_x="size_x", size_param_y="size_y")

    def init(self):
        shape = self.INPUT.shape
        needed = self.select + 2
        if self.select_salience.strip().lower() != "none":
            needed = max(needed, int(self.select_salience) + 1)
        if shape[-1] < needed or len(shape) > 2:
            raise ValueError(f"INPUT must have rows of at least {needed} columns for "
                             f"select={self.select} and select_salience="
                             f"{self.select_salience}, not shape {shape}")
        self._points = self.INPUT.reshape(1, -1) if self.INPUT.ndim == 1 else self.INPUT
        self._cols = np.arange(self.size_x, dtype=np.float32) + 0.5
        self._rows = np.arange(self.size_y, dtype=np.float32) + 0.5

    def tick(self):
        points = self._points
        n = points.shape[0] if self.COUNT is None else min(int(self.COUNT.flat[0]),
                                                            points.shape[0])
        x = points[:n, self.select] * self.size_x
        y = points[:n, self.select + 1] * self.size_y
        column = self.select_salience.strip().lower()
        salience = np.ones(n, np.float32) if column == "none" else points[:n, int(column)]
        salience = salience * self.scale
        k = -0.5 / (self.sigma * self.sigma)
        across = np.exp(k * (self._cols[None, :] - x[:, None]) ** 2)
        down = np.exp(k * (self._rows[None, :] - y[:, None]) ** 2) * salience[:, None]
        np.matmul(down.T, across, out=self.OUTPUT)
