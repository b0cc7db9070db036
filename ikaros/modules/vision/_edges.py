"""Helpers of the edge detectors: gradient operators with fixed kernels, Gaussian
derivative kernels and non-maximum suppression, all vectorised."""
from __future__ import annotations

import math

import numpy as np

from ikaros.module import Input, Module, Output

from ._cv import GrayImage, as_image, image_shape, interior, opencv, shrunk


class GradientOperator(Module):
    """Base of Sobel, Prewitt and Roberts: correlates the gray image (the intensity of a
    colour one; a vector is a one-row image) with the fixed kernels ``kx`` and ``ky`` (or
    those ``kernels()`` gives) and writes ``combine(dx, dy)`` for the part of the image
    where the kernels fit (kernel size - 1 smaller, as in Ikaros 2), or for every pixel when
    ``full_size()`` (the border filled by reflection). ``smoothing()`` above 0 blurs the
    image with a Gaussian of that standard deviation first."""

    kx: np.ndarray
    ky: np.ndarray
    INPUT = Input("the image: gray (rows, cols), or colour (3, rows, cols) whose intensity "
                  "is used")
    OUTPUT = Output("the gradient magnitude, kernel size - 1 rows and columns smaller than "
                    "INPUT")

    def configure(self):
        self.cv2 = opencv()

    def kernel_pair(self) -> tuple[np.ndarray, np.ndarray]:
        """The correlation kernels of dx and dy (float32, of one shape)."""
        return self.kx, self.ky

    def full_size(self) -> bool:
        """Whether OUTPUT has the size of INPUT rather than the valid part."""
        return False

    def smoothing(self) -> float:
        """The standard deviation of a Gaussian blur before the gradient; 0: none."""
        return 0.0

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape:
            shape = image_shape(shape)
            size = shape[-2:] if self.full_size() else shrunk(shape[-2:],
                                                              *self.kernel_pair()[0].shape)
            self.set_output_shape("OUTPUT", size)

    def init(self):
        image = as_image(self.INPUT)
        self._gray = GrayImage(image)
        self._kx, self._ky = self.kernel_pair()
        rows, cols = self._kx.shape
        full = image.shape[-2:]
        self._smooth = np.zeros(full, np.float32)
        self._dx, self._dy = np.zeros(full, np.float32), np.zeros(full, np.float32)
        out = as_image(self.OUTPUT)
        if self.full_size():
            self.dx, self.dy = self._dx, self._dy
        else:
            self.dx = interior(self._dx, rows // 2, cols // 2, *out.shape)
            self.dy = interior(self._dy, rows // 2, cols // 2, *out.shape)
        self.out = out

    def tick(self):
        cv2, gray = self.cv2, self._gray()
        sigma = self.smoothing()
        if sigma > 0:
            cv2.GaussianBlur(gray, (0, 0), sigma, dst=self._smooth,
                             borderType=cv2.BORDER_REFLECT)
            gray = self._smooth
        cv2.filter2D(gray, -1, self._kx, dst=self._dx, borderType=cv2.BORDER_REFLECT)
        cv2.filter2D(gray, -1, self._ky, dst=self._dy, borderType=cv2.BORDER_REFLECT)
        self.combine(self.dx, self.dy)

    def combine(self, dx: np.ndarray, dy: np.ndarray) -> None:
        """Write OUTPUT (``self.out``, a 2-D view) from the gradients; the magnitude by
        default."""
        self.cv2.magnitude(dx, dy, magnitude=self.out)


def gaussian_derivative_kernels(sigma: float) -> tuple[np.ndarray, np.ndarray]:
    """Correlation kernels (float32, 2·ceil(3σ) + 1 square) that give the x (rightward) and
    y (downward) derivatives of the image smoothed by a Gaussian of standard deviation
    ``sigma``, scaled so that a ramp of slope 1 gives exactly 1."""
    if sigma <= 0:
        raise ValueError(f"scale must be above 0, not {sigma}")
    radius = math.ceil(3.0 * sigma)
    r = np.arange(-radius, radius + 1, dtype=np.float64)
    x, y = r[None, :], r[:, None]
    g = np.exp(-(x * x + y * y) / (2.0 * sigma * sigma))
    gx = x * g
    gx /= (gx * x).sum()
    return gx.astype(np.float32), np.ascontiguousarray(gx.T, np.float32)


def non_maximum_suppression(magnitude: np.ndarray, dx: np.ndarray, dy: np.ndarray,
                            out: np.ndarray, threshold: float = 0.0) -> None:
    """Write into ``out`` the magnitude where it is a maximum along the gradient direction
    (the direction rounded to one of 4: horizontal, vertical and the two diagonals; above
    the neighbour behind, at least the neighbour ahead) and above ``threshold``; 0
    elsewhere. Image borders count as 0."""
    rows, cols = magnitude.shape
    padded = np.zeros((rows + 2, cols + 2), np.float32)
    padded[1:-1, 1:-1] = magnitude
    sector = np.rint(np.arctan2(dy, dx) * (4.0 / np.pi)).astype(np.int8) % 4
    keep = magnitude > threshold
    # (row, col) offsets of the neighbour ahead for the sectors 0°, 45°, 90° and 135°
    for k, (dr, dc) in enumerate(((0, 1), (1, 1), (1, 0), (1, -1))):
        ahead = padded[1 + dr:1 + dr + rows, 1 + dc:1 + dc + cols]
        behind = padded[1 - dr:1 - dr + rows, 1 - dc:1 - dc + cols]
        here = sector == k
        keep &= ~here | ((magnitude > behind) & (magnitude >= ahead))
    np.multiply(magnitude, keep, out=out)
