"""TemplatePolygonTransform: where a found template lies in the image, ready to draw."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._template import (TEMPLATE, found, normalised, plausible_polygon, project, rows)


class TemplatePolygonTransform(Module):
    """Turns a found template into positions to draw and to look at. When RESULT says found,
    the outline of its template (the RESULT's template row of TEMPLATE_CORNERS) is mapped by
    HOMOGRAPHY into the image; if it maps to a convex polygon covering ``min_area_fraction``
    to ``max_area_fraction`` of the ``image_width`` x ``image_height`` frame, PATH is one
    row with its corners and the first corner again (x0 y0 ... x3 y3 x0 y0: a closed line
    for the path widget), LOCATION is (x, y, 1) with the polygon's centre (the mean of its
    corners), and MATCHED_FEATURES lists the points that support it: the tracked points
    (TRACKED_POINTS, such as PyramidalLucasKanadeTracker's CURRENT_POINTS) when that input
    is connected and has rows, otherwise the rows of KEYPOINTS named by INLIERS (rows
    (keypoint, template keypoint)), at most ``max_features``. All positions are fractions
    0..1 of the frame (docs/images.md); the inputs are in its pixels. When nothing is found,
    or the outline is implausible, PATH and MATCHED_FEATURES are empty and LOCATION keeps
    the last centre with 0 as its third value. This is this project's reading of the
    Ikaros 3 interface (docs/vision-tracking.md)."""

    image_width = Parameter(320, "the width of the frame the points are given in",
                            range=(1, None))
    image_height = Parameter(240, "the height of that frame", range=(1, None))
    min_area_fraction = Parameter(0.002, "the smallest area of the mapped outline, as a part "
                                  "of the frame", range=(0, None))
    max_area_fraction = Parameter(0.9, "the largest area of the mapped outline, as a part of "
                                  "the frame", range=(0, None))
    max_features = Parameter(512, "the most points listed in MATCHED_FEATURES", type="int",
                             range=(1, None), fixed=True)

    HOMOGRAPHY = Input("the transform from template points to the image", size="3, 3")
    RESULT = Input("the RESULT of RobustTransformEstimator or of a tracker")
    TEMPLATE_CORNERS = Input("one row of outline corners x0 y0 ... x3 y3 per template")
    KEYPOINTS = Input("the image's points, one row (x, y) each, in pixels")
    INLIERS = Input("the inlier matches: rows (keypoint, template keypoint)")
    TRACKED_POINTS = Input("tracked points (x, y) in pixels, listed instead of the inliers",
                           optional=True)
    PATH = Output("the outline in the image: x0 y0 ... x3 y3 x0 y0, in 0..1", dynamic=True,
                  capacity="1, 10")
    LOCATION = Output("the outline's centre (x, y) in 0..1, and 1 when found, else 0",
                      shape="3")
    MATCHED_FEATURES = Output("the supporting points, one row (x, y) each, in 0..1",
                              dynamic=True, capacity="@max_features, 2")

    def _lost(self):
        self.PATH.clear()
        self.MATCHED_FEATURES.clear()
        self.LOCATION[2] = 0

    def tick(self):
        if not found(self.RESULT):
            return self._lost()
        template = int(np.asarray(self.RESULT).ravel()[TEMPLATE])
        corners = rows(self.TEMPLATE_CORNERS, 8, "TEMPLATE_CORNERS")
        if not 0 <= template < len(corners):
            return self._lost()
        outline = project(self.HOMOGRAPHY, corners[template].reshape(4, 2))
        plausible, _ = plausible_polygon(outline, self.image_width, self.image_height,
                                         self.min_area_fraction, self.max_area_fraction)
        if not plausible:
            return self._lost()
        size = (self.image_width, self.image_height)
        self.PATH.set(normalised(np.vstack([outline, outline[:1]]), *size).reshape(1, 10))
        self.LOCATION[:2] = normalised(outline.mean(axis=0, keepdims=True), *size)[0]
        self.LOCATION[2] = 1
        points = rows(self.TRACKED_POINTS, 2, "TRACKED_POINTS")
        if not len(points):
            keypoints = rows(self.KEYPOINTS, 2, "KEYPOINTS")
            index = rows(self.INLIERS, 2, "INLIERS")[:, 0].astype(np.int64)
            points = keypoints[index[(index >= 0) & (index < len(keypoints))]]
        self.MATCHED_FEATURES.set(normalised(points[:int(self.max_features)], *size))
