"""SobelEdgeDetector: Sobel gradient."""
import numpy as np

from ikaros.module import Parameter

from ._edges import GradientOperator


class SobelEdgeDetector(GradientOperator):
    """The Sobel gradient of the gray image (the intensity of a colour one). dx is the
    convolution with the Sobel kernel [[-1, 0, 1], [-2, 0, 2], [-1, 0, 1]] (the kernel
    flipped, as Ikaros 2 computes it: dx is positive where the image gets darker to the
    right, the opposite of a correlation), dy the same downwards (positive where it gets
    darker downwards). ``type`` chooses the output: sqrt (the magnitude, √(dx² + dy²)), abs
    (|dx| + |dy|), dx, dy, abs(dx) or abs(dy). In an Ikaros 2 file (as the golden outputs
    show) the output is the part of the image where the 3 x 3 kernel fits, 2 rows and
    columns smaller. Ikaros 3's class has the parameter ``sigma`` (default 1) and an
    output of the input's size; in an Ikaros 3 file OUTPUT has the input's size (the border
    filled by reflection) and the image is first blurred with a Gaussian of standard
    deviation ``sigma`` pixels. (Only Ikaros 3's interface is known, not its formulas: that
    sigma blurs before the Sobel kernels, and the border, are this project's reading.) In an
    Ikaros 2 file ``sigma`` is 0 unless set (no blur, as the original)."""

    type = Parameter("sqrt", "what to output", options="sqrt/abs/dx/dy/abs(dx)/abs(dy)")
    sigma = Parameter(0.0, "standard deviation of a Gaussian blur before the gradient, in "
                      "pixels; 0: none", range=(0, None), default_v3=1.0)
    kx = np.array([[1, 0, -1], [2, 0, -2], [1, 0, -1]], np.float32)
    ky = np.ascontiguousarray(kx.T)

    def full_size(self):
        return self.dialect == "3"

    def smoothing(self):
        return self.sigma

    def combine(self, dx, dy):
        kind, out = self.type, self.out
        if kind == "sqrt":
            self.cv2.magnitude(dx, dy, magnitude=out)
        elif kind == "abs":
            np.abs(dx, out=out)
            out += np.abs(dy)
        elif kind in ("dx", "dy"):
            np.copyto(out, dx if kind == "dx" else dy)
        else:
            np.abs(dx if kind == "abs(dx)" else dy, out=out)
