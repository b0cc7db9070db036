"""RobertsEdgeDetector: Roberts cross gradient magnitude."""
import numpy as np

from ._edges import GradientOperator


class RobertsEdgeDetector(GradientOperator):
    """The magnitude of the Roberts cross gradient of the gray image (the intensity of a
    colour one): √(d1² + d2²) with d1 = I[r, c] - I[r-1, c-1] and d2 = I[r, c-1] -
    I[r-1, c], the two diagonal differences of each 2 x 2 block. The output is 1 row and
    column smaller than the input; OUTPUT[r, c] is the block of input rows r, r+1 and
    columns c, c+1."""

    kx = np.array([[-1, 0], [0, 1]], np.float32)
    ky = np.array([[0, -1], [1, 0]], np.float32)
