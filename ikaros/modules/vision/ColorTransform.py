"""ColorTransform: colour-space conversions."""
import numpy as np

from ikaros.module import Parameter

from ._colour import ThreePlanes
from ._cv import opencv
from ._colour_spaces import (RGB_TO_XYZ, XYZ_TO_RGB, lab_to_xyz, mix, rgb_to_lab_float32,
                             srgb_compress, srgb_expand, xyz_to_lab)


class ColorTransform(ThreePlanes):
    """Converts colours between spaces. The inputs are first divided by ``scale`` (255 for
    8-bit levels). RGB is **linear** (no sRGB gamma) with the BT.709 primaries and the D65
    white: RGB->XYZ multiplies by the matrix X = 0.412453 R + 0.357581 G + 0.180423 B,
    Y = 0.212670 R + 0.715160 G + 0.072169 B, Z = 0.019334 R + 0.119193 G + 0.950227 B, and
    XYZ->RGB by its published inverse (3.240479 -1.537150 -0.498535; -0.969256 1.875992
    0.041556; 0.055648 -0.204043 1.057311), unclamped. RGB->Lab gives CIE L*a*b* of that XYZ
    relative to the white (0.950456, 1, 1.088754): f(t) = t^(1/3) above 0.008856, else
    7.787 t + 16/116 (negative t included); L = 116 f(Y) - 16, not below 0, a = 500
    (f(X) - f(Y)), b = 200 (f(Y) - f(Z)), so a grey of 0.5 gives L = 76.07; it is computed in
    single precision as the original does (the golden outputs of Ikaros 2 and 3 agree to
    the last bit, which matters where a and b are near 0). Lab->RGB is the inverse, clamped
    to 0..1. RGB->rgI gives the chromaticities r = R / (R+G+B) and g = G / (R+G+B) (1/3
    each where R+G+B is 0) and I = R+G+B (the sum, after the division by ``scale``; the
    input of ColorClassifier). With ``gamma="srgb"`` (this project's option; OpenCV's
    convention) RGB values are sRGB-encoded instead: expanded to linear light before
    RGB->Lab and RGB->XYZ and compressed after Lab->RGB and XYZ->RGB, so a grey of 0.5 gives
    L = 53.39. The image comes on INPUT (3, rows, cols) or on INPUT0..2 (R, G, B or the
    planes of the source space; a vector is a one-row plane), and goes out on OUTPUT and on
    OUTPUT0..2.

    Ikaros 2 does not use ``transform``: whatever it says, the golden outputs of Ikaros 2
    are RGB->Lab of the inputs (a defect). So in an Ikaros 2 file ``ignore_transform`` is
    yes by default and every module converts RGB->Lab, as the original; set
    ``ignore_transform="no"`` (this project's correction) for the conversion ``transform``
    names. In an Ikaros 3 file it is no by default, as Ikaros 3 converts as ``transform``
    says (its golden outputs). (That ``scale`` divides the inputs is known for RGB->Lab and
    RGB->rgI; the other conversions are taken to do the same.)"""

    transform = Parameter("RGB->Lab", "the conversion",
                          options="RGB->Lab/RGB->XYZ/Lab->RGB/XYZ->RGB/RGB->rgI")
    scale = Parameter(1.0, "divides the inputs (255 for 8-bit levels)")
    ignore_transform = Parameter(True, "yes: RGB->Lab whatever transform says, as Ikaros 2 "
                                 "(a defect); no: the conversion transform names",
                                 default_v3=False)
    gamma = Parameter("none", "none: linear RGB, as in Ikaros; srgb: sRGB-encoded RGB "
                      "(OpenCV's conversion)", options="none/srgb")

    def configure(self):
        self.cv2 = opencv()

    def init(self):
        super().init()
        if self.scale == 0:
            raise ValueError("scale must not be 0 (it divides the inputs)")
        self._image = np.zeros(self.OUTPUT.shape, np.float64)
        self._scaled = np.zeros(self.OUTPUT.shape, np.float32)
        self._total = np.zeros(self.OUTPUT.shape[1:], np.float32)
        self._nonzero = np.zeros(self.OUTPUT.shape[1:], bool)

    def tick(self):
        transform = "RGB->Lab" if self.ignore_transform else self.transform
        if transform == "RGB->rgI":
            self._rgi()
            return
        if transform == "RGB->Lab" and self.gamma == "none":
            for src, dst in zip(self.planes_in, self._scaled):
                np.divide(src, np.float32(self.scale), out=dst)
            rgb_to_lab_float32(self._scaled, self.OUTPUT)
            return
        image = self._image
        for src, dst in zip(self.planes_in, image):
            np.divide(src, self.scale, out=dst)
        self.OUTPUT[...] = getattr(self, "_" + transform.replace("->", "_to_"))(image)

    def _rgi(self):
        """r = R/(R+G+B), g = G/(R+G+B) (1/3 where the sum is 0), I = (R+G+B) / scale, in
        float32 on buffers made once (the chromaticities do not depend on scale). With
        scale 1 the sum is made in I's plane itself."""
        red, green, blue = self.planes_in
        out = self.OUTPUT
        total = out[2] if self.scale == 1 else self._total
        cv2 = self.cv2
        cv2.add(red, green, dst=total)
        cv2.add(total, blue, dst=total)
        if cv2.countNonZero(total) == total.size:
            cv2.divide(red, total, dst=out[0])
            cv2.divide(green, total, dst=out[1])
        else:
            np.not_equal(total, 0.0, out=self._nonzero)
            for src, dst in ((red, out[0]), (green, out[1])):
                dst.fill(1.0 / 3.0)
                np.divide(src, total, out=dst, where=self._nonzero)
        if total is not out[2]:
            np.divide(total, self.scale, out=out[2])

    def _linear(self, rgb):
        return srgb_expand(rgb) if self.gamma == "srgb" else rgb

    def _encoded(self, rgb):
        return srgb_compress(rgb) if self.gamma == "srgb" else rgb

    def _RGB_to_XYZ(self, rgb):
        return mix(RGB_TO_XYZ, self._linear(rgb))

    def _XYZ_to_RGB(self, xyz):
        return self._encoded(mix(XYZ_TO_RGB, xyz))

    def _RGB_to_Lab(self, rgb):
        return xyz_to_lab(self._RGB_to_XYZ(rgb))

    def _Lab_to_RGB(self, lab):
        return np.clip(self._XYZ_to_RGB(lab_to_xyz(lab)), 0.0, 1.0)
