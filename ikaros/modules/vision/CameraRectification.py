"""CameraRectification: undistorts an image with a camera model (Ikaros 3)."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import check_image, planes

TERMS = 14          # k1 k2 p1 p2 k3 k4 k5 k6 s1 s2 s3 s4 tx ty


class CameraRectification(Module):
    """Undistorts an image with an OpenCV-style camera model, as Ikaros 3's class does; the
    output keeps the input's camera matrix. DISTORTION holds k1, k2, p1, p2 [, k3 [, k4,
    k5, k6 [, s1, s2, s3, s4 [, τx, τy]]]] (missing terms are 0). For each output pixel
    (x = column, y = row, in pixels from the top-left pixel's centre): xn = (x - cx) / fx
    and yn = (y - cy) / fy with cx = K[0, 2], cy = K[1, 2] (the skew K[0, 1] is ignored);
    r² = xn² + yn²; radial = (1 + k1 r² + k2 r⁴ + k3 r⁶) / (1 + k4 r² + k5 r⁴ + k6 r⁶)
    (the numerator alone where the denominator is 0); xd = xn·radial + 2 p1 xn yn +
    p2 (r² + 2 xn²) + s1 r² + s2 r⁴ and yd = yn·radial + p1 (r² + 2 yn²) + 2 p2 xn yn +
    s3 r² + s4 r⁴; the pixel takes the value at (fx xd + cx, fy yd + cy) of the input,
    interpolated bilinearly (x0, y0 the truncated coordinates, x1 = min(x0 + 1, cols - 1),
    y1 likewise) when that point lies in [0, cols - 1] x [0, rows - 1], and
    ``border_value`` elsewhere. The map is computed in float32 and again only when the
    image size, the camera matrix or the distortion change. τx and τy are ignored, with a
    warning once if they are not 0. If fx or fy is 0 the module warns once and leaves
    OUTPUT as it is. A colour image is undistorted plane by plane."""

    border_value = Parameter(0.0, "the value of output pixels that map outside the image")
    INPUT = Input("the image: gray (rows, cols) or colour (3, rows, cols)")
    CAMERA_MATRIX = Input("the camera matrix K, 3 x 3: fx 0 cx; 0 fy cy; 0 0 1")
    DISTORTION = Input("the distortion coefficients k1, k2, p1, p2 and optionally k3, k4, "
                       "k5, k6, s1, s2, s3, s4, tx, ty")
    OUTPUT = Output("the undistorted image, shaped like INPUT", shape="INPUT.shape")

    def init(self):
        check_image(self.INPUT.shape)
        if self.CAMERA_MATRIX.shape != (3, 3):
            raise ValueError(f"CAMERA_MATRIX must be 3 x 3, not {self.CAMERA_MATRIX.shape}")
        if self.DISTORTION.size < 4:
            raise ValueError(f"DISTORTION needs at least 4 values (k1, k2, p1, p2), not "
                             f"{self.DISTORTION.size}")
        self._key = None
        self._warned = set()

    def _warn_once(self, what: str, message: str) -> None:
        if what not in self._warned:
            self._warned.add(what)
            self.warning(message)

    def tick(self):
        k = self.CAMERA_MATRIX.astype(np.float32)
        if k[0, 0] == 0 or k[1, 1] == 0:
            self._warn_once("focal", "fx or fy of CAMERA_MATRIX is 0: the image is not "
                            "undistorted")
            return
        key = (k.tobytes(), self.DISTORTION.tobytes())
        if key != self._key:
            self._key = key
            self._make_map(k)
        top_left, top_right, bottom_left, bottom_right = self._corners
        wx, wy, inside = self._wx, self._wy, self._inside
        for src, dst in zip(planes(self.INPUT), planes(self.OUTPUT)):
            flat = src.reshape(-1)
            top = flat[top_left] + wx * (flat[top_right] - flat[top_left])
            bottom = flat[bottom_left] + wx * (flat[bottom_right] - flat[bottom_left])
            dst[...] = np.where(inside, top + wy * (bottom - top), self.border_value)

    def _make_map(self, k):
        d = np.zeros(TERMS, np.float32)
        values = self.DISTORTION.reshape(-1)[:TERMS].astype(np.float32)
        d[:values.size] = values
        k1, k2, p1, p2, k3, k4, k5, k6, s1, s2, s3, s4, tx, ty = d
        if tx != 0 or ty != 0:
            self._warn_once("tilt", "the tilt terms tx and ty of DISTORTION are ignored")
        rows, cols = self.INPUT.shape[-2:]
        fx, fy, cx, cy = k[0, 0], k[1, 1], k[0, 2], k[1, 2]
        y, x = np.mgrid[0:rows, 0:cols].astype(np.float32)
        xn, yn = (x - cx) / fx, (y - cy) / fy
        r2 = xn * xn + yn * yn
        r4, r6 = r2 * r2, r2 * r2 * r2
        numerator = 1 + k1 * r2 + k2 * r4 + k3 * r6
        denominator = 1 + k4 * r2 + k5 * r4 + k6 * r6
        with np.errstate(divide="ignore", invalid="ignore"):
            radial = np.where(denominator != 0, numerator / denominator, numerator)
        xd = xn * radial + 2 * p1 * xn * yn + p2 * (r2 + 2 * xn * xn) + s1 * r2 + s2 * r4
        yd = yn * radial + p1 * (r2 + 2 * yn * yn) + 2 * p2 * xn * yn + s3 * r2 + s4 * r4
        sx, sy = fx * xd + cx, fy * yd + cy
        self._inside = (sx >= 0) & (sx <= cols - 1) & (sy >= 0) & (sy <= rows - 1)
        sx, sy = np.where(self._inside, sx, 0), np.where(self._inside, sy, 0)
        x0, y0 = sx.astype(np.intp), sy.astype(np.intp)
        x1, y1 = np.minimum(x0 + 1, cols - 1), np.minimum(y0 + 1, rows - 1)
        self._wx, self._wy = sx - x0, sy - y0
        self._corners = (y0 * cols + x0, y0 * cols + x1, y1 * cols + x0, y1 * cols + x1)
