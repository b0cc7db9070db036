"""PrewittEdgeDetector: Prewitt gradient magnitude."""
import numpy as np

from ._edges import GradientOperator


class PrewittEdgeDetector(GradientOperator):
    """The magnitude √(dx² + dy²) of the Prewitt gradient of the gray image (the intensity
    of a colour one): dx is the correlation with [[-1, 0, 1], [-1, 0, 1], [-1, 0, 1]], dy
    the same for downwards. As in Ikaros 2 the output is the part of the image where the
    3 x 3 kernel fits, 2 rows and columns smaller."""

    kx = np.array([[-1, 0, 1], [-1, 0, 1], [-1, 0, 1]], np.float32)
    ky = np.ascontiguousarray(kx.T)
