"""FeaturePointBoxes: a small box around each feature point, for drawing."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._template import normalised, rows


class FeaturePointBoxes(Module):
    """Draws feature points: BOXES has one row (x, y, width, height) per point of POINTS
    (rows (x, y) in pixels of an ``image_width`` x ``image_height`` frame), a square of
    ``box_size`` pixels centred on the point, as fractions 0..1 of the frame's width and
    height (docs/images.md): the target-boxes widget's default ``xywh`` form. At most
    ``max_points`` boxes, in the order of the points. The box form is this project's
    reading of the Ikaros 3 interface, which only names the ports."""

    image_width = Parameter(320, "the width of the frame the points are given in",
                            range=(1, None))
    image_height = Parameter(240, "the height of that frame", range=(1, None))
    box_size = Parameter(6.0, "the side of each box, in pixels", range=(0, None))
    max_points = Parameter(8192, "the most boxes", type="int", range=(1, None), fixed=True)

    POINTS = Input("the points, one row (x, y) each, in pixels")
    BOXES = Output("one row (x, y, width, height) per point, in 0..1", dynamic=True,
                   capacity="@max_points, 4")

    def tick(self):
        points = rows(self.POINTS, 2, "POINTS")[:int(self.max_points)]
        size = np.array([self.image_width, self.image_height], np.float64)
        half = self.box_size / 2
        corner = normalised(points - half, *size)
        extent = np.broadcast_to(self.box_size / size, corner.shape)
        self.BOXES.set(np.hstack([corner, extent]))
