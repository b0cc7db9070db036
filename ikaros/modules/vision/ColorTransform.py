"""ColorTransform: colour-space conversions."""
import numpy as np

from ikaros.module import Parameter

from ._colour import ThreePlanes

CODES = {"RGB->Lab": "COLOR_RGB2Lab", "RGB->XYZ": "COLOR_RGB2XYZ",
         "Lab->RGB": "COLOR_Lab2RGB", "XYZ->RGB": "COLOR_XYZ2RGB"}


class ColorTransform(ThreePlanes):
    """Converts colours between spaces with OpenCV's cvtColor (D65 white):
    RGB->Lab gives CIE L*a*b* (L 0..100, a and b about -128..127) from sRGB values 0..1
    (gamma-expanded first), Lab->RGB the reverse (OpenCV computes these with tables,
    within about 0.2 of the exact L*a*b* values); RGB->XYZ and XYZ->RGB use the linear
    sRGB matrix on the values as they are (OpenCV applies no gamma there). RGB->rgI gives
    the chromaticities r = R / (R+G+B) and g = G / (R+G+B) (0 where R+G+B is 0) and the
    intensity I = (R+G+B) / 3, the input of ColorClassifier. The result is multiplied by
    ``scale``. The image comes on INPUT (3, rows, cols) or on INPUT0..2 (R, G, B or the
    planes of the source space), and goes out on OUTPUT and on OUTPUT0..2."""

    transform = Parameter("RGB->Lab", "the conversion",
                          options="RGB->Lab/RGB->XYZ/Lab->RGB/XYZ->RGB/RGB->rgI")
    scale = Parameter(1.0, "multiplies the result")

    def init(self):
        super().init()
        shape = self.OUTPUT.shape[1:]
        self._pixels = np.zeros(shape + (3,), np.float32)
        self._converted = np.zeros(shape + (3,), np.float32)
        self._sum = np.zeros(shape, np.float32)
        self._nonzero = np.zeros(shape, bool)

    def compute(self):
        cv2, out = self.cv2, self.OUTPUT
        if self.transform == "RGB->rgI":
            red, green, blue = self.planes_in
            np.add(red, green, out=self._sum)
            self._sum += blue
            np.greater(self._sum, 0.0, out=self._nonzero)
            for src, dst in ((red, out[0]), (green, out[1])):
                dst.fill(0.0)
                np.divide(src, self._sum, out=dst, where=self._nonzero)
            np.multiply(self._sum, 1.0 / 3.0, out=out[2])
        else:
            cv2.merge(self.planes_in, dst=self._pixels)
            cv2.cvtColor(self._pixels, getattr(cv2, CODES[self.transform]),
                         dst=self._converted)
            np.copyto(out, self._converted.transpose(2, 0, 1))
        if self.scale != 1.0:
            out *= self.scale
