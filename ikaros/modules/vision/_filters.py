"""Base classes of the neighbourhood filters: a filter whose output is the part of the image
where its whole kernel fits (as in Ikaros 2, the output is kernel size - 1 rows and columns
smaller than the input), for gray and colour images alike."""
from __future__ import annotations

import threading

import numpy as np

from ikaros.module import Input, Module, Output

from ._cv import as_image, image_shape, interior, opencv, planes, shrunk


_work = threading.local()


def work_plane(shape: tuple) -> np.ndarray:
    """A float32 work plane of this shape, one per thread and shape, made once and shared
    by the filters that tick in that thread (each uses it only during its tick), so that
    a chain of filters keeps one plane in the cache instead of one each."""
    planes = _work.__dict__.setdefault("planes", {})
    plane = planes.get(shape)
    if plane is None:
        plane = planes[shape] = np.zeros(shape, np.float32)
    return plane


class ValidFilter(Module):
    """Filters each plane into a full-size work plane with OpenCV and copies the part where
    the kernel fits into OUTPUT. Subclasses give ``kernel_shape`` and ``filter``; those with
    a kernel that depends on parameters give ``kernel_key`` and ``make_kernel``, and the
    kernel is made again when the key changes between ticks."""

    INPUT = Input("the image: gray (rows, cols), colour (3, rows, cols) or a vector (one "
                  "row)")
    OUTPUT = Output("the filtered image, gray or colour as INPUT, kernel size - 1 rows and "
                    "columns smaller (the pixels where the whole kernel fits)")

    def configure(self):
        self.cv2 = opencv()

    def kernel_shape(self) -> tuple[int, int]:
        """The (rows, cols) of the kernel, from the parameters. It is read once in init
        (``self.kernel_rows``, ``self.kernel_cols``): the size is fixed for the run."""
        raise NotImplementedError

    def kernel_key(self) -> tuple:
        """The parameters the kernel is made from."""
        return ()

    def make_kernel(self) -> None:
        """Make the kernel (and write kernel outputs) from the current parameters."""

    def filter(self, src: np.ndarray, dst: np.ndarray) -> None:
        """Filter one gray plane into ``dst`` of the same size."""
        raise NotImplementedError

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape:
            shape = image_shape(shape)
            rows, cols = self.kernel_shape()
            if rows < 1 or cols < 1:
                raise ValueError(f"the kernel size must be at least 1, not {rows} x {cols}")
            self.set_output_shape("OUTPUT", shrunk(shape, rows, cols))

    def init(self):
        rows, cols = self.kernel_rows, self.kernel_cols = self.kernel_shape()
        image, out = as_image(self.INPUT), as_image(self.OUTPUT)
        self._plane_shape = image.shape[-2:]
        self._valid_part = (rows // 2, cols // 2) + out.shape[-2:]
        self._pairs = list(zip(planes(image), planes(out)))
        self._key = self.kernel_key()
        self.make_kernel()

    def tick(self):
        key = self.kernel_key()
        if key != self._key:
            self._key = key
            self.make_kernel()
        full = work_plane(self._plane_shape)
        valid = interior(full, *self._valid_part)
        for src, dst in self._pairs:
            self.filter(src, full)
            np.copyto(dst, valid)


class KernelFilter(ValidFilter):
    """A ValidFilter that correlates each plane with ``self.kernel`` (float32), made by
    ``make_kernel``, with ``cv2.filter2D``."""

    kernel: np.ndarray

    def filter(self, src, dst):
        self.cv2.filter2D(src, -1, self.kernel, dst=dst, borderType=self.cv2.BORDER_REFLECT)


def odd_kernel_size(size: int, name: str = "kernel_size") -> int:
    """``size`` if it is a positive odd number, else ValueError."""
    if size < 1 or size % 2 == 0:
        raise ValueError(f"{name} must be a positive odd number, not {size}")
    return int(size)


def kernel_grid(size: int) -> tuple[np.ndarray, np.ndarray]:
    """Column (x) and row (y) offsets from the centre of a size x size kernel, as float64
    (1, size) and (size, 1) arrays."""
    r = np.arange(size, dtype=np.float64) - (size - 1) / 2.0
    return r[None, :], r[:, None]


def balance(kernel: np.ndarray) -> np.ndarray:
    """The kernel with its positive entries scaled to sum 1 and its negative entries to sum
    -1 (the ``normalize`` of Ikaros 2's DoGFilter and LoGFilter); a sign with no entries is
    left as it is."""
    kernel = np.array(kernel, np.float64)
    for part in (kernel > 0, kernel < 0):
        total = abs(kernel[part].sum())
        if total > 0:
            kernel[part] /= total
    return kernel
