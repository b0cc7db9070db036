"""CameraRectification: undistorts an image with an OpenCV-style camera model (Ikaros 3)."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

F32 = np.float32


def source_points(shape, K, distortion):
    """For each output pixel of an image of ``shape`` (rows, cols), where it is found in
    the distorted input: arrays (x, y) in float32 (MODULES-V3 §20)."""
    rows, cols = shape
    d = np.zeros(14, F32)
    d[:min(14, distortion.size)] = distortion[:14]
    k1, k2, p1, p2, k3, k4, k5, k6, s1, s2, s3, s4 = d[:12]
    fx, fy, cx, cy = F32(K[0, 0]), F32(K[1, 1]), F32(K[0, 2]), F32(K[1, 2])
    y, x = np.mgrid[0:rows, 0:cols].astype(F32)
    xn, yn = (x - cx) / fx, (y - cy) / fy
    r2 = xn * xn + yn * yn
    r4, r6 = r2 * r2, r2 * r2 * r2
    numerator = 1 + k1 * r2 + k2 * r4 + k3 * r6
    denominator = 1 + k4 * r2 + k5 * r4 + k6 * r6
    safe = np.where(denominator == 0, F32(1), denominator)
    radial = np.where(denominator == 0, numerator, numerator / safe)
    xd = xn * radial + 2 * p1 * xn * yn + p2 * (r2 + 2 * xn * xn) + s1 * r2 + s2 * r4
    yd = yn * radial + p1 * (r2 + 2 * yn * yn) + 2 * p2 * xn * yn + s3 * r2 + s4 * r4
    return (fx * xd + cx).astype(F32), (fy * yd + cy).astype(F32)


class CameraRectification(Module):
    """Removes lens distortion: each output pixel (column x, row y) takes the input at the
    point where the camera model CAMERA_MATRIX (fx, fy, cx, cy; the skew is ignored) with
    DISTORTION (k1, k2, p1, p2 [, k3 [, k4, k5, k6 [, s1, s2, s3, s4 [, τx, τy]]]]: radial
    as a rational function, tangential and thin-prism terms) maps it, sampled bilinearly,
    or ``border_value`` where that point is outside the image. The output uses the input's
    camera matrix (no new optimal matrix), computed in float32 as Ikaros 3 does; the map is
    rebuilt when the image size, camera matrix or distortion changes. INPUT is gray
    (rows × cols) or colour (3 × rows × cols). The tilt terms τx, τy are ignored, with a
    warning when they are not 0; with fx or fy 0 the tick is skipped, with a warning. New
    in Ikaros 3."""

    border_value = Parameter(0.0, "the value of pixels whose source is outside the image")
    INPUT = Input("the image: rows × cols, or 3 × rows × cols")
    CAMERA_MATRIX = Input("the 3 × 3 camera matrix")
    DISTORTION = Input("the distortion coefficients (at least k1, k2, p1, p2)", flatten=True)
    OUTPUT = Output("the undistorted image", size_set="INPUT")

    def init(self):
        problems = []
        if self.INPUT.ndim not in (2, 3) or (self.INPUT.ndim == 3 and
                                             self.INPUT.shape[0] != 3):
            problems.append(f"INPUT must be rows × cols or 3 × rows × cols, not "
                            f"{self.INPUT.shape}")
        if self.CAMERA_MATRIX.shape != (3, 3):
            problems.append(f"CAMERA_MATRIX must be 3 × 3, not {self.CAMERA_MATRIX.shape}")
        if self.DISTORTION.size < 4:
            problems.append(f"DISTORTION needs at least 4 values, not {self.DISTORTION.size}")
        if problems:
            self.fatal_error("; ".join(problems))
        self._key = None
        self._warned = set()

    def _warn_once(self, what, message):
        if what not in self._warned:
            self._warned.add(what)
            self.warning(message)

    def _map(self, rows, cols):
        key = (self.CAMERA_MATRIX.tobytes(), self.DISTORTION.tobytes())
        if key != self._key:
            self._key = key
            if self.DISTORTION.size >= 14 and self.DISTORTION[12:14].any():
                self._warn_once("tilt", "the tilt terms of DISTORTION are ignored")
            x, y = source_points((rows, cols), self.CAMERA_MATRIX, self.DISTORTION)
            inside = (x >= 0) & (x <= cols - 1) & (y >= 0) & (y <= rows - 1)
            x0 = np.where(inside, x, 0).astype(np.int64)
            y0 = np.where(inside, y, 0).astype(np.int64)
            fx, fy = np.where(inside, x - x0, 0), np.where(inside, y - y0, 0)
            self._sample = (inside, y0, x0, np.minimum(y0 + 1, rows - 1),
                            np.minimum(x0 + 1, cols - 1), fx.astype(F32), fy.astype(F32))
        return self._sample

    def tick(self):
        K = self.CAMERA_MATRIX
        if K[0, 0] == 0 or K[1, 1] == 0:
            self._warn_once("focal", "fx or fy of CAMERA_MATRIX is 0: the image is not "
                            "rectified")
            return
        planes = self.INPUT if self.INPUT.ndim == 3 else self.INPUT[None]
        out = self.OUTPUT if self.OUTPUT.ndim == 3 else self.OUTPUT[None]
        inside, y0, x0, y1, x1, fx, fy = self._map(*planes.shape[1:])
        for plane, target in zip(planes, out):
            top = plane[y0, x0] * (1 - fx) + plane[y0, x1] * fx
            bottom = plane[y1, x0] * (1 - fx) + plane[y1, x1] * fx
            target[...] = np.where(inside, top * (1 - fy) + bottom * fy, self.border_value)
