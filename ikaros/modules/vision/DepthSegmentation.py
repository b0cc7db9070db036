"""DepthSegmentation: the pixels of one object, cut out by its depth range."""
from ikaros.module import Input, Module, Output, Parameter


class DepthSegmentation(Module):
    """Marks the pixels of INPUT whose depth lies in the range of OBJECT — (nearest,
    farthest, ...) as DepthHistogram gives it, nearest included and farthest excluded — and
    whose column lies between mask_left and mask_right (fractions of the width): OUTPUT is 1
    there and 0 elsewhere."""

    mask_left = Parameter(0.0, "columns left of this fraction of the width are left out")
    mask_right = Parameter(1.0, "columns right of this fraction of the width are left out")
    INPUT = Input("the depth image")
    OBJECT = Input("the depth range (nearest, farthest, ...)")
    OUTPUT = Output("1 for the object's pixels, 0 elsewhere", size_set="INPUT")

    def init(self):
        if self.INPUT.ndim != 2:
            raise ValueError(f"INPUT must be a depth image (rows, cols), not shape "
                             f"{self.INPUT.shape}")

    def tick(self):
        cols = self.INPUT.shape[1]
        left, right = int(round(self.mask_left * cols)), int(round(self.mask_right * cols))
        near, far = float(self.OBJECT.flat[0]), float(self.OBJECT.flat[1])
        self.OUTPUT.fill(0)
        if far > near and right > left:
            part = self.INPUT[:, left:right]
            self.OUTPUT[:, left:right] = (part >= near) & (part < far)
