"""DepthSegmentation: the pixels of one object, cut out by its depth range."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import as_image, image_shape


class DepthSegmentation(Module):
    """Marks the pixels of INPUT whose depth lies in the range of OBJECT — (nearest,
    farthest, ...) as DepthHistogram gives it, both ends included (Ikaros 2's golden outputs
    show a depth of 0 in the range 0 .. 0 marked) — and whose column lies between mask_left
    and mask_right (fractions of the width): OUTPUT is 1 there and 0 elsewhere. A vector is
    a one-row image. (How the masks round to columns is this module's reading.)"""

    mask_left = Parameter(0.0, "columns left of this fraction of the width are left out")
    mask_right = Parameter(1.0, "columns right of this fraction of the width are left out")
    INPUT = Input("the depth image")
    OBJECT = Input("the depth range (nearest, farthest, ...)")
    OUTPUT = Output("1 for the object's pixels, 0 elsewhere", size_set="INPUT")

    def init(self):
        image_shape(self.INPUT.shape, gray=True)
        if self.OBJECT.size < 2:
            raise ValueError(f"OBJECT must hold the nearest and farthest depth, not "
                             f"{self.OBJECT.size} value(s)")
        self._image, self._out = as_image(self.INPUT), as_image(self.OUTPUT)

    def tick(self):
        cols = self._image.shape[1]
        left, right = int(round(self.mask_left * cols)), int(round(self.mask_right * cols))
        near, far = np.float32(self.OBJECT.flat[0]), np.float32(self.OBJECT.flat[1])
        self._out.fill(0)
        if right > left:
            part = self._image[:, left:right]
            self._out[:, left:right] = (part >= near) & (part <= far)
