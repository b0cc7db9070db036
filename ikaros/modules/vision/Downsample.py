"""Downsample: halves the image size."""
from ikaros.module import Input, Module, Output

from ._cv import check_image, opencv, planes, with_size


class Downsample(Module):
    """Halves the width and height of the image: each output pixel is the mean of a 2 x 2
    block of input pixels (OpenCV's area resize); an odd last row or column is dropped. A
    colour image is halved plane by plane. (Ikaros 2 describes its class as halving
    without interpolation; the block mean is this module's choice, as it does not alias
    fine patterns.)"""

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
            self.cv2.resize(src, self._size, dst=dst, interpolation=self.cv2.INTER_AREA)
