"""Upsample: doubles the image size."""
from ikaros.module import Input, Module, Output

from ._cv import as_image, image_shape, opencv, planes, with_size


class Upsample(Module):
    """Doubles the width and height of the image by repeating each pixel in a 2 x 2 block
    (OpenCV's nearest-neighbour resize), as Ikaros 2 does (its golden outputs). A colour
    image is doubled plane by plane; a vector is a one-row image and gives two rows."""

    INPUT = Input("the image: gray (rows, cols) or colour (3, rows, cols)")
    OUTPUT = Output("the image at twice the size (2 rows, 2 cols)")

    def configure(self):
        self.cv2 = opencv()

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape:
            shape = image_shape(shape)
            self.set_output_shape("OUTPUT", with_size(shape, 2 * shape[-2], 2 * shape[-1]))

    def init(self):
        self._pairs = list(zip(planes(as_image(self.INPUT)), planes(self.OUTPUT)))
        self._size = self.OUTPUT.shape[:-3:-1]

    def tick(self):
        for src, dst in self._pairs:
            self.cv2.resize(src, self._size, dst=dst, interpolation=self.cv2.INTER_NEAREST)
