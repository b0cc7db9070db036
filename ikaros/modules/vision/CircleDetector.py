"""CircleDetector: one circle from a list of edge elements."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class CircleDetector(Module):
    """Finds the strongest circle in a list of edge elements (the EDGE_LIST of
    EdgeSegmentation: rows x, y, orientation, strength; the first EDGE_LIST_SIZE rows are
    used). It is a Hough transform that uses the edge orientation: each element votes, for
    every radius from ``min_radius`` to ``max_radius`` pixels, for the two points at that
    distance along its gradient direction (either way, so bright and dark discs are both
    found). The centre is the point with most votes (votes on a 1-pixel grid, smoothed over
    3 x 3); the diameter is twice the median distance to it of the elements whose
    gradient points along the radius (within 25°) at a distance in the radius range.
    POSITION is (x, y, support): the centre in pixels (x = column, y = row, as in
    EDGE_LIST) and the fraction of the elements that support the circle; DIAMETER is in
    pixels; all are 0 when no element is given. HISTX and HISTDX are 15-bin histograms of
    the elements' x positions (over their range) and of the x component of their gradient
    direction (over -1..1), for display. With fewer than 3 elements (too few for a circle)
    every output is 0: in all the golden cases of Ikaros 2 (at most one element) its
    outputs, histograms included, are 0. The Ikaros 2 class found the circle from
    histograms of positions and orientations, by formulas the reference does not give;
    this one votes, which also works with several objects in view, and so its values are
    this project's reading throughout."""

    min_radius = Parameter(20.0, "smallest radius searched, in pixels")
    max_radius = Parameter(100.0, "largest radius searched, in pixels")
    EDGE_LIST = Input("edge elements, one row each: x, y, orientation (radians), strength")
    EDGE_LIST_SIZE = Input("how many rows of EDGE_LIST are used", optional=True)
    HISTX = Output("histogram of the elements' x positions", shape="15")
    HISTDX = Output("histogram of the x component of the gradient direction", shape="15")
    POSITION = Output("the centre x, y and the fraction of supporting elements", shape="3")
    DIAMETER = Output("the circle's diameter in pixels", shape="1")

    def init(self):
        self._edges = self.EDGE_LIST.reshape(1, -1) if self.EDGE_LIST.ndim == 1 \
            else self.EDGE_LIST
        shape = self._edges.shape
        if len(shape) != 2 or shape[1] < 3:
            raise ValueError(f"EDGE_LIST must have rows of x, y, orientation (at least 3 "
                             f"columns), not shape {shape}")
        if not 0 < self.min_radius <= self.max_radius:
            raise ValueError("min_radius must be above 0 and at most max_radius")

    def tick(self):
        edges = self._edges
        n = edges.shape[0]
        if self.EDGE_LIST_SIZE is not None:
            given = float(self.EDGE_LIST_SIZE.flat[0])
            n = int(min(max(given, 0), n)) if np.isfinite(given) else 0
        for out in (self.POSITION, self.DIAMETER, self.HISTX, self.HISTDX):
            out.fill(0.0)
        if n < 3:
            return
        x, y, angle = (edges[:n, i].astype(np.float64) for i in range(3))
        self.HISTX[...] = np.histogram(x, 15, (x.min(), x.max() + 1e-9))[0]
        self.HISTDX[...] = np.histogram(np.cos(angle), 15, (-1.0, 1.0))[0]
        cx, cy = self._centre(x, y, np.cos(angle), np.sin(angle))
        dx, dy = x - cx, y - cy
        distance = np.hypot(dx, dy)
        radial = np.abs(np.cos(angle) * dx + np.sin(angle) * dy) > np.cos(np.radians(25)) * \
            distance
        support = radial & (distance >= self.min_radius) & (distance <= self.max_radius)
        if support.any():
            self.POSITION[:] = cx, cy, support.mean()
            self.DIAMETER[0] = 2.0 * np.median(distance[support])

    def _centre(self, x, y, cos, sin):
        radii = np.arange(self.min_radius, self.max_radius + 0.5)
        vx = np.concatenate([x[:, None] + cos[:, None] * radii,
                             x[:, None] - cos[:, None] * radii]).ravel()
        vy = np.concatenate([y[:, None] + sin[:, None] * radii,
                             y[:, None] - sin[:, None] * radii]).ravel()
        x0, y0 = np.floor(vx.min()), np.floor(vy.min())
        cols, rows = int(vx.max() - x0) + 3, int(vy.max() - y0) + 3
        index = np.rint(vy - y0).astype(np.int64) * cols + np.rint(vx - x0).astype(np.int64)
        votes = np.bincount(index, minlength=rows * cols).reshape(rows, cols).astype(float)
        padded = np.pad(votes, 1)
        smoothed = sum(padded[1 + i:1 + i + rows, 1 + j:1 + j + cols]
                       for i in (-1, 0, 1) for j in (-1, 0, 1))
        r, c = np.unravel_index(np.argmax(smoothed), smoothed.shape)
        # refine to the weighted mean of the 3 x 3 votes around the peak
        window = padded[r:r + 3, c:c + 3]
        offsets = np.arange(-1, 2)
        total = window.sum()
        return (x0 + c + (window.sum(axis=0) @ offsets) / total,
                y0 + r + (window.sum(axis=1) @ offsets) / total)
