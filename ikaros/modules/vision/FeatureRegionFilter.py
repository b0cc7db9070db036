"""FeatureRegionFilter: keeps the feature points of the central region of the image."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._template import central_region, flag, inside, rows


class FeatureRegionFilter(Module):
    """Passes on the feature points (KEYPOINTS, pixels of an ``image_width`` x
    ``image_height`` frame) and their DESCRIPTORS, all of them, or, while RESTRICT is above
    0, only those in the centred region of ``region`` of the frame's width and of its
    height (the region TemplateFeatureBank learns from, so that a template is looked for
    where it would be learned). At most ``max_features`` points, in the order they come.
    Descriptors must have ``descriptor_size`` values (ALIKED's 128 in Ikaros 3; give 32 for
    ORBFeatureExtractor's): other lengths are an error at the start that says so. The
    behaviour is this project's reading of the Ikaros 3 interface, which only names the
    ports (docs/vision-tracking.md)."""

    image_width = Parameter(320, "the width of the frame the points are given in",
                            range=(1, None))
    image_height = Parameter(240, "the height of that frame", range=(1, None))
    region = Parameter(0.5, "the part of the width and height, centred, kept while RESTRICT "
                       "is on", range=(0, 1))
    max_features = Parameter(512, "the most points passed on", type="int", range=(1, None),
                             fixed=True)
    descriptor_size = Parameter(128, "the number of values of a descriptor", type="int",
                                range=(1, None), fixed=True)

    KEYPOINTS = Input("the points, one row (x, y) each, in pixels")
    DESCRIPTORS = Input("the descriptor of each point, one row each")
    RESTRICT = Input("above 0: keep only the points in the central region", size="1")
    FILTERED_KEYPOINTS = Output("the points kept, one row (x, y) each", dynamic=True,
                                capacity="@max_features, 2")
    FILTERED_DESCRIPTORS = Output("their descriptors", dynamic=True,
                                  capacity="@max_features, @descriptor_size")

    def init(self):
        shape = self.DESCRIPTORS.shape
        columns = shape[-1] if len(shape) == 2 else None
        if columns is not None and columns != self.descriptor_size:
            raise ValueError(f"DESCRIPTORS have rows of {columns} values but descriptor_size "
                             f"is {self.descriptor_size}: set descriptor_size=\"{columns}\"")

    def tick(self):
        points = rows(self.KEYPOINTS, 2, "KEYPOINTS")
        descriptors = rows(self.DESCRIPTORS, int(self.descriptor_size), "DESCRIPTORS")
        n = min(len(points), len(descriptors))
        keep = np.arange(n)
        if flag(self.RESTRICT):
            region = central_region(self.image_width, self.image_height, self.region)
            keep = keep[inside(points[:n], region)]
        keep = keep[:int(self.max_features)]
        self.FILTERED_KEYPOINTS.set(points[keep])
        self.FILTERED_DESCRIPTORS.set(descriptors[keep])
