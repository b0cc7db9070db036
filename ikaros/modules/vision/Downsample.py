"""Downsample: halves the image size."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import check_image, opencv, planes, with_size


class Downsample(Module):
    """Halves the width and height of the image: the output pixel (r, c) is the mean of
    the 2 x 2 block of input pixels (2r .. 2r + 1, 2c .. 2c + 1), as Ikaros 2 and Ikaros 3
    compute it (their golden outputs show the block mean; OpenCV's area resize). An odd last
    row or column is dropped. A colour image is halved plane by plane. With
    ``method="subsample"`` (this project's option) the output pixel is the top-left pixel
    of its block, (2r, 2c), without interpolation."""

    method = Parameter("mean", "mean: the mean of each 2 x 2 block, as the original; "
                       "subsample: the top-left pixel of each block", options="mean/subsample")

    INPUT = Input("the image: gray (rows, cols) or colour (3, rows, cols)")
    OUTPUT = Output("the image at half the size (rows // 2, cols // 2)")

    def configure(self):
        self.cv2 = opencv()

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape:
            check_image(shape)
            if shape[-2] < 2 or shape[-1] < 2:
                raise ValueError(f"INPUT must be at least 2 x 2 to halve, not {shape}")
            self.set_output_shape("OUTPUT", with_size(shape, shape[-2] // 2, shape[-1] // 2))

    def init(self):
        rows, cols = self.OUTPUT.shape[-2:]
        self._pairs = [(src[:2 * rows, :2 * cols], dst)
                       for src, dst in zip(planes(self.INPUT), planes(self.OUTPUT))]
        self._size = (cols, rows)

    def tick(self):
        for src, dst in self._pairs:
            if self.method == "mean":
                self.cv2.resize(src, self._size, dst=dst, interpolation=self.cv2.INTER_AREA)
            else:
                np.copyto(dst, src[::2, ::2])
