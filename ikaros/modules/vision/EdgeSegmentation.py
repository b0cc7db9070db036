"""EdgeSegmentation: a list of edge elements from an edge image and its gradients."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import check_gray


class EdgeSegmentation(Module):
    """Selects edge elements: the pixels of the edge image INPUT (for example the MAXIMA of
    GaussianEdgeDetector) on a grid of every ``grid``-th row and column whose value is
    above ``threshold``; with ``normalize`` INPUT is first divided by its maximum. OUTPUT is
    the (normalised) edge image at the selected pixels and 0 elsewhere. EDGE_LIST has one
    row per element, in row-major order, (x, y, orientation, strength): the column and
    row, the gradient direction atan2(DY, DX) in radians (y points down) and the
    (normalised) edge value. EDGE_ELEMENTS has the same elements as line segments
    (x0, y0, x1, y1) along the edge (across the gradient), ``grid`` pixels long, for
    drawing. Rows after EDGE_LIST_SIZE are 0; at most ``max_edges`` elements are kept.
    (The reference describes Ikaros 2's class in a sentence, and no golden output reaches
    it: the layout of the lists and the normalisation are this project's reading.)"""

    threshold = Parameter(0.1, "edge values above this are selected")
    max_edges = Parameter(1000, "the most elements listed")
    grid = Parameter(1, "look at every grid-th row and column")
    normalize = Parameter(True, "divide INPUT by its maximum first")
    INPUT = Input("the edge image (rows, cols)")
    DX = Input("the derivative to the right (rows, cols)")
    DY = Input("the derivative downwards (rows, cols)")
    OUTPUT = Output("the edge image at the selected pixels, 0 elsewhere", shape="INPUT.shape")
    EDGE_LIST = Output("one row per element: x, y, orientation, strength",
                       shape="@max_edges, 4")
    EDGE_ELEMENTS = Output("one row per element: the segment x0, y0, x1, y1 along the edge",
                           shape="@max_edges, 4")
    EDGE_LIST_SIZE = Output("the number of elements listed", shape="1")

    def init(self):
        shapes = {n: getattr(self, n).shape for n in ("INPUT", "DX", "DY")}
        for name, shape in shapes.items():
            check_gray(shape, name)
        if len(set(shapes.values())) > 1:
            raise ValueError(f"INPUT, DX and DY must have the same size, not {shapes}")
        if self.grid < 1 or self.max_edges < 1:
            raise ValueError("grid and max_edges must be at least 1")

    def tick(self):
        step = self.grid
        edges = self.INPUT
        scale = 1.0
        if self.normalize:
            top = float(edges.max())
            scale = 1.0 / top if top > 0 else 1.0
        on_grid = edges[::step, ::step]
        rows, cols = np.nonzero(on_grid * scale > self.threshold)
        limit = self.EDGE_LIST.shape[0]
        rows, cols = rows[:limit] * step, cols[:limit] * step
        n = rows.size
        strength = edges[rows, cols] * scale
        angle = np.arctan2(self.DY[rows, cols], self.DX[rows, cols])
        self.OUTPUT.fill(0.0)
        self.OUTPUT[rows, cols] = strength
        table = self.EDGE_LIST
        table[n:] = 0.0
        table[:n, 0], table[:n, 1], table[:n, 2], table[:n, 3] = cols, rows, angle, strength
        # a segment across the gradient: along (-sin, cos) of the gradient direction
        half = 0.5 * step
        ux, uy = -np.sin(angle) * half, np.cos(angle) * half
        segments = self.EDGE_ELEMENTS
        segments[n:] = 0.0
        segments[:n, 0], segments[:n, 1] = cols - ux, rows - uy
        segments[:n, 2], segments[:n, 3] = cols + ux, rows + uy
        self.EDGE_LIST_SIZE[0] = n
