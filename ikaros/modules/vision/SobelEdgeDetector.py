"""SobelEdgeDetector: Sobel gradient."""
import numpy as np

from ikaros.module import Parameter

from ._edges import GradientOperator


class SobelEdgeDetector(GradientOperator):
    """The Sobel gradient of the gray image (the intensity of a colour one): dx is the
    correlation with [[-1, 0, 1], [-2, 0, 2], [-1, 0, 1]] (positive where the image gets
    brighter to the right), dy the same for downwards. ``type`` chooses the output: sqrt
    (the magnitude, √(dx² + dy²)), abs (|dx| + |dy|), dx, dy, abs(dx) or abs(dy). As in
    Ikaros 2 the output is the part of the image where the 3 x 3 kernel fits, 2 rows and
    columns smaller."""

    type = Parameter("sqrt", "what to output", options="sqrt/abs/dx/dy/abs(dx)/abs(dy)")
    kx = np.array([[-1, 0, 1], [-2, 0, 2], [-1, 0, 1]], np.float32)
    ky = np.ascontiguousarray(kx.T)

    def combine(self, dx, dy):
        kind, out = self.type, self.OUTPUT
        if kind == "sqrt":
            self.cv2.magnitude(dx, dy, magnitude=out)
        elif kind == "abs":
            np.abs(dx, out=out)
            out += np.abs(dy)
        elif kind in ("dx", "dy"):
            np.copyto(out, dx if kind == "dx" else dy)
        else:
            np.abs(dx if kind == "abs(dx)" else dy, out=out)
