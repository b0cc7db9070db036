"""Helpers shared by the vision modules: the OpenCV import, image shapes and planes, the
gray version of an image, and 8-bit conversion.

Images follow docs/images.md: float32, gray ``(rows, cols)`` or colour ``(3, rows, cols)``
with the planes red, green, blue, values 0..1. Colour images are planar, so each plane is a
contiguous gray image that OpenCV reads and writes in place (``dst=``) with no conversion:
filter a colour image by filtering its planes.
"""
from __future__ import annotations

import numpy as np

from ikaros.module import require


def opencv():
    """The ``cv2`` module, or a ``MissingDependency`` that says
    ``pip install 'ikaros[vision]'``. Call it in ``configure`` so a model that needs OpenCV
    fails at load when it is missing."""
    return require("cv2", "opencv-python-headless", extra="vision")


def is_colour(shape: tuple) -> bool:
    """Whether a shape is a colour image ``(3, rows, cols)``."""
    return len(shape) == 3 and shape[0] == 3


def image_shape(shape: tuple | None, port: str = "INPUT", gray: bool = False) -> tuple:
    """The image shape of an input as the original reads it: a gray ``(rows, cols)`` or
    (unless ``gray``) colour ``(3, rows, cols)`` shape as it is, and a vector ``(n,)`` as
    the one-row image ``(1, n)`` (Ikaros 2 holds every array as a matrix). ``ValueError``
    for anything else."""
    if shape is not None and len(shape) == 1 and shape[0] > 0:
        return (1, int(shape[0]))
    if gray:
        check_gray(shape, port)
    else:
        check_image(shape, port)
    return tuple(shape)


def as_image(array: np.ndarray) -> np.ndarray:
    """A 2-D (or colour 3-D) view of an array that ``image_shape`` accepts: a vector is
    viewed as one row, without a copy, so that writing to the view writes the array."""
    return array.reshape(1, -1) if array.ndim == 1 else array


def warn_other_version(module, ikaros2: tuple, ikaros3: tuple) -> None:
    """Warn (from ``init``) when the module's element sets parameters of the other Ikaros
    version than its file's, which a class with both versions' interfaces does not use."""
    v3 = module.dialect == "3"
    given = getattr(module.element, "attrs", {})
    unused = [p for p in (ikaros2 if v3 else ikaros3) if p in given]
    if unused:
        module.warning(f"{', '.join(unused)}: not used in an Ikaros {'3' if v3 else '2'} "
                       f"file (see the class description)")


def warn_one_row(module, port: str = "INPUT", result: str = "the output is always 0") -> None:
    """Warn (from ``init``) when a one-row image reaches a class whose result is then
    meaningless; the original runs it alike."""
    shape = getattr(module, port.replace("-", "_")).shape
    if len(shape) == 1 or shape[-2] == 1:
        module.warning(f"{port} is a one-row image {tuple(shape)}: {result}, as in the "
                       f"original")


def check_image(shape: tuple | None, port: str = "INPUT") -> None:
    """Raise ``ValueError`` unless ``shape`` is a gray or colour image."""
    if shape is None or not (len(shape) == 2 or is_colour(shape)) or 0 in shape:
        raise ValueError(f"{port} must be a gray (rows, cols) or colour (3, rows, cols) "
                         f"image, not an array of shape {shape}")


def check_gray(shape: tuple | None, port: str = "INPUT") -> None:
    """Raise ``ValueError`` unless ``shape`` is a gray image ``(rows, cols)``."""
    if shape is None or len(shape) != 2 or 0 in shape:
        raise ValueError(f"{port} must be a gray image (rows, cols), not an array of shape "
                         f"{shape}")


def planes(image: np.ndarray) -> list[np.ndarray]:
    """The gray planes of an image, as views: ``[image]`` for gray, ``[R, G, B]`` for
    colour."""
    return [image] if image.ndim == 2 else list(image)


def with_size(shape: tuple, rows: int, cols: int) -> tuple:
    """``shape`` with its last two axes (rows, cols) replaced: gray stays gray and colour
    stays colour."""
    return tuple(shape[:-2]) + (int(rows), int(cols))


def shrunk(shape: tuple, kernel_rows: int, kernel_cols: int | None = None) -> tuple:
    """The shape of the part of an image where a kernel of this size fits entirely (a
    'valid' filter): ``kernel - 1`` fewer rows and columns. ``ValueError`` if nothing is
    left."""
    kernel_cols = kernel_rows if kernel_cols is None else kernel_cols
    rows, cols = shape[-2] - kernel_rows + 1, shape[-1] - kernel_cols + 1
    if rows < 1 or cols < 1:
        raise ValueError(f"the image ({shape[-2]} x {shape[-1]}) is smaller than the "
                         f"kernel ({kernel_rows} x {kernel_cols})")
    return with_size(shape, rows, cols)


def interior(image: np.ndarray, top: int, left: int, rows: int, cols: int) -> np.ndarray:
    """A view of ``rows`` x ``cols`` pixels of every plane, starting at (top, left)."""
    return image[..., top:top + rows, left:left + cols]


class GrayImage:
    """The gray version of an input image, made once per tick without copies when possible:
    a gray input is used as it is (a view), and a colour input gives its intensity, the mean
    of its three planes, written into one buffer allocated here."""

    def __init__(self, image: np.ndarray):
        self.image = image
        self.buffer = None if image.ndim == 2 else np.zeros(image.shape[1:], np.float32)

    def __call__(self) -> np.ndarray:
        if self.buffer is None:
            return self.image
        np.mean(self.image, axis=0, out=self.buffer)
        return self.buffer


class Uint8Image:
    """Converts a 0..1 float image of a fixed shape to 8-bit levels for OpenCV functions
    that need them, as the image files do (docs/images.md): clipped to 0..1, then
    level = round(255 · value). Both buffers are allocated here, once."""

    def __init__(self, shape: tuple):
        self.cv2 = opencv()
        self.clipped = np.zeros(shape, np.float32)
        self.levels = np.zeros(shape, np.uint8)

    def __call__(self, image: np.ndarray) -> np.ndarray:
        np.clip(image, 0.0, 1.0, out=self.clipped)
        # 255 · value rounded to the nearest level (OpenCV's saturating conversion)
        self.cv2.convertScaleAbs(self.clipped, dst=self.levels, alpha=255.0)
        return self.levels


# Image positions that modules pass to each other (FOCUS, positions, bounds) are (x, y)
# fractions of the image's width and height, 0..1 from the left and top edges, so that they
# hold for images of any size. The pixel in row r and column c covers x in
# [c / cols, (c + 1) / cols); its centre is at ((c + 0.5) / cols, (r + 0.5) / rows)
# (docs/images.md, "Positions in an image").

def pixel_of(x: float, y: float, rows: int, cols: int) -> tuple[int, int]:
    """The (row, col) of the pixel that holds the position (x, y), clamped to the image."""
    return (min(max(int(np.floor(y * rows)), 0), rows - 1),
            min(max(int(np.floor(x * cols)), 0), cols - 1))


def position_of(row: float, col: float, rows: int, cols: int) -> tuple[float, float]:
    """The position (x, y) of the centre of the pixel (row, col)."""
    return (col + 0.5) / cols, (row + 0.5) / rows
