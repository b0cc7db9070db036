"""PrewittEdgeDetector: Prewitt gradient magnitude."""
import numpy as np

from ikaros.module import Parameter

from ._edges import GradientOperator

# The two kernels whose magnitude Ikaros 2's class computes (its golden outputs fit them
# exactly, up to a rotation of the pair): Prewitt's with two corner entries moved.
IKAROS2 = (np.array([[-2, 0, 1], [-1, 0, 1], [0, 0, 1]], np.float32),
           np.array([[0, -1, -1], [0, 0, 0], [0, 1, 1]], np.float32))
PREWITT = (np.array([[-1, 0, 1], [-1, 0, 1], [-1, 0, 1]], np.float32),
           np.array([[-1, -1, -1], [0, 0, 0], [1, 1, 1]], np.float32))


class PrewittEdgeDetector(GradientOperator):
    """The gradient magnitude √(dx² + dy²) of the gray image (the intensity of a colour
    one), where dx and dy are the correlations with two 3 x 3 kernels. The output is the
    part of the image where the kernels fit, 2 rows and columns smaller. Ikaros 2's class
    does not use Prewitt's kernels: its outputs (the golden files) are the magnitude for
    [[-2, 0, 1], [-1, 0, 1], [0, 0, 1]] and [[0, -1, -1], [0, 0, 0], [0, 1, 1]], Prewitt's
    with the corner entries of the left column misplaced (a defect). That is the default
    (``kernels="ikaros2"``); ``kernels="prewitt"`` (this project's correction) uses
    Prewitt's [[-1, 0, 1], [-1, 0, 1], [-1, 0, 1]] and its transpose."""

    kernels = Parameter("ikaros2", "ikaros2: the original's kernels (a defect); prewitt: "
                        "Prewitt's kernels", options="ikaros2/prewitt")

    def kernel_pair(self):
        return IKAROS2 if self.kernels == "ikaros2" else PREWITT
