"""The computations of Ikaros 2's GaussianEdgeDetector and CannyEdgeDetector, as their
golden outputs show them: Gaussian-derivative kernels, gradients on the part of the image
where the kernel fits, the gradient direction rounded to one of the 8 neighbours, and
non-maximum suppression that leaves the border of the result as it is. All vectorised."""
from __future__ import annotations

import math

import numpy as np

from ._cv import interior

# (column, row) offsets of the neighbour ahead for the directions k · 45°, k = 0 .. 7
# (y pointing down, as the rows)
_OFFSETS = np.array([(round(math.cos(k * math.pi / 4)), round(math.sin(k * math.pi / 4)))
                     for k in range(8)], np.float32)


def ikaros2_kernels(scale: float) -> tuple[np.ndarray, np.ndarray]:
    """The derivative kernels dGx = ∂G/∂x and dGy = ∂G/∂y (rows y, columns x; float32) of
    G = exp(-(x² + y²) / scale²) on the offsets -r .. r, r = ceil(2 · scale): for scale 1
    the 5 x 5 kernels the original outputs (dGx = -2x · exp(-(x² + y²)))."""
    if scale <= 0:
        raise ValueError(f"scale must be above 0, not {scale}")
    radius = math.ceil(2.0 * scale)
    r = np.arange(-radius, radius + 1, dtype=np.float64)
    x, y = r[None, :], r[:, None]
    kx = -2.0 * x / (scale * scale) * np.exp(-(x * x + y * y) / (scale * scale))
    return kx.astype(np.float32), np.ascontiguousarray(kx.T, np.float32)


def warn_scale(module) -> None:
    """Warn (from ``init``) when ``scale`` is not 1, which the original cannot run."""
    if module.scale != 1:
        module.warning(f"scale {module.scale}: the original runs only scale 1 (with "
                  f"another its output sizes are unresolved); this kernel is this project's "
                  f"reading")


class ValidGradient:
    """dx and dy of a gray image: its correlations with kx and ky where they fit (the
    image's border of the kernel's radius left out), on buffers made once."""

    def __init__(self, cv2, kx: np.ndarray, ky: np.ndarray, shape: tuple):
        self.cv2, self.kx, self.ky = cv2, kx, ky
        radius = kx.shape[0] // 2
        self._full = [np.zeros(shape, np.float32) for _ in range(2)]
        rows, cols = shape[0] - 2 * radius, shape[1] - 2 * radius
        self.dx, self.dy = (interior(f, radius, radius, rows, cols) for f in self._full)

    def __call__(self, gray: np.ndarray) -> None:
        for kernel, full in zip((self.kx, self.ky), self._full):
            self.cv2.filter2D(gray, -1, kernel, dst=full, borderType=self.cv2.BORDER_REFLECT)


class Suppression:
    """Non-maximum suppression as Ikaros 2 does it, for images of one shape: the direction
    of (dx, dy) is rounded to the nearest of the 8 neighbours (k · 45°), and an inner pixel
    keeps its magnitude when it is above the magnitude of the neighbour behind it and at
    least that of the neighbour ahead; the pixels of the border keep theirs."""

    def __init__(self, shape: tuple):
        self.sector = np.zeros(shape, np.int64)
        self._angle = np.zeros(shape, np.float32)
        self._keep = np.zeros((shape[0] - 2, shape[1] - 2), bool)
        self._here = np.zeros_like(self._keep)

    def directions(self, dx: np.ndarray, dy: np.ndarray) -> np.ndarray:
        """The sector k (0 .. 7) of each pixel's gradient direction, in ``self.sector``."""
        np.arctan2(dy, dx, out=self._angle)
        self._angle *= np.float32(4.0 / np.pi)
        np.rint(self._angle, out=self._angle)
        np.copyto(self.sector, self._angle, casting="unsafe")
        self.sector %= 8
        return self.sector

    def offsets(self, out_x: np.ndarray, out_y: np.ndarray) -> None:
        """Write the (column, row) offsets of the neighbour ahead of each pixel."""
        np.take(_OFFSETS[:, 0], self.sector, out=out_x)
        np.take(_OFFSETS[:, 1], self.sector, out=out_y)

    def __call__(self, magnitude: np.ndarray, out: np.ndarray) -> None:
        """Write the suppressed ``magnitude`` into ``out`` (after ``directions``)."""
        rows, cols = magnitude.shape
        np.copyto(out, magnitude)
        if rows < 3 or cols < 3:
            return
        inner = magnitude[1:-1, 1:-1]
        keep, here = self._keep, self._here
        keep.fill(True)
        sector = self.sector[1:-1, 1:-1]
        for k, (dc, dr) in enumerate(_OFFSETS.astype(int)):
            ahead = magnitude[1 + dr:rows - 1 + dr, 1 + dc:cols - 1 + dc]
            behind = magnitude[1 - dr:rows - 1 - dr, 1 - dc:cols - 1 - dc]
            np.equal(sector, k, out=here)
            keep &= ~here | ((inner > behind) & (inner >= ahead))
        np.multiply(inner, keep, out=out[1:-1, 1:-1])


def hysteresis(cv2, maxima: np.ndarray, low: float, high: float, out: np.ndarray) -> None:
    """1 in ``out`` at the inner pixels (not the border) whose ``maxima`` are above ``low``
    and that are connected (8-neighbours, through such pixels) to one above ``high``."""
    out.fill(0.0)
    inner = maxima[1:-1, 1:-1]
    if inner.size == 0:
        return
    weak = (inner > low).astype(np.uint8)
    count, labels = cv2.connectedComponents(weak, connectivity=8)
    strong = np.zeros(count, bool)
    strong[labels[inner > high]] = True
    strong[0] = False
    out[1:-1, 1:-1] = strong[labels]
