"""RobustTransformEstimator: finds a template in the image from matched feature points."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import opencv
from ._template import (AREA, COVERAGE, FOUND, INLIER_RATIO, MEAN_ERROR, MEAN_SCORE, POINTS,
                        RESULT_DESCRIPTION, RESULT_SIZE, TEMPLATE, identity,
                        plausible_polygon, polygon_area, project, rows, template_ranges)


class RobustTransformEstimator(Module):
    """Decides whether, and where, a stored template is in the current image. For each
    template (at most ``max_templates``) the homography that maps its points to the image
    points they were matched to (CORRESPONDENCES, at most ``max_matches`` of the best
    scores) is estimated with RANSAC (OpenCV's findHomography, ``ransac_iterations``
    iterations, points within ``reprojection_threshold`` pixels count as inliers). A
    template counts as found when it has at least ``min_inliers`` inliers, an inlier ratio
    of at least ``min_inlier_ratio``, a mean match score of its inliers of at least
    ``min_mean_match_score``, a mean reprojection error of at most ``max_mean_error``
    pixels, inliers whose convex hull covers at least ``min_source_coverage`` of the
    template's outline (TEMPLATE_CORNERS), and an outline that maps to a convex polygon
    covering ``min_area_fraction`` to ``max_area_fraction`` of the ``image_width`` x
    ``image_height`` frame. Of the templates found, the one with the most inliers wins
    (the lower mean error on a tie). HOMOGRAPHY maps its points to the image (the identity
    when none is found), INLIERS lists its inlier matches as rows (keypoint, template
    keypoint), and RESULT is (found, template, points, inlier ratio, mean error in pixels,
    mean match score, area fraction, coverage) of it, found 1 (all 0, template -1, when none
    is found). The port layouts are this project's reading of the Ikaros 3 interface
    (docs/vision-tracking.md); CORRESPONDENCES may come from FeatureMatcher (OpenCV) or from
    a matcher with LightGlueFeatureMatcher's output."""

    reprojection_threshold = Parameter(3.0, "the largest distance in pixels of an inlier "
                                       "from where the homography puts its template point",
                                       range=(0, None))
    min_inliers = Parameter(6, "the fewest inliers of a found template", type="int",
                            range=(4, None))
    min_inlier_ratio = Parameter(0.0, "the smallest share of a template's matches that are "
                                 "inliers", range=(0, 1))
    min_mean_match_score = Parameter(0.0, "the smallest mean match score of the inliers")
    min_source_coverage = Parameter(0.0, "the smallest part of the template's outline "
                                    "covered by the convex hull of its inliers", range=(0, 1))
    max_mean_error = Parameter(3.0, "the largest mean reprojection error of the inliers, in "
                               "pixels", range=(0, None))
    image_width = Parameter(320, "the width of the frame the points are given in",
                            range=(1, None))
    image_height = Parameter(240, "the height of that frame", range=(1, None))
    min_area_fraction = Parameter(0.005, "the smallest area of the mapped outline, as a part "
                                  "of the frame", range=(0, None))
    max_area_fraction = Parameter(0.75, "the largest area of the mapped outline, as a part "
                                  "of the frame", range=(0, None))
    ransac_iterations = Parameter(256, "the most RANSAC iterations per template", type="int",
                                  range=(1, None))
    max_matches = Parameter(512, "the most matches used (the best scores)", type="int",
                            range=(1, None), fixed=True)
    max_templates = Parameter(16, "the most templates tried", type="int", range=(1, None))

    KEYPOINTS = Input("the image's points, one row (x, y) each, in pixels")
    TEMPLATE_KEYPOINTS = Input("the templates' points (TemplateFeatureBank)")
    TEMPLATE_RANGES = Input("one row (first, count) per template")
    TEMPLATE_CORNERS = Input("one row of outline corners x0 y0 ... x3 y3 per template")
    CORRESPONDENCES = Input("one row (template, keypoint, template keypoint, score) per match")
    HOMOGRAPHY = Output("the 3 x 3 transform from the found template's points to the image",
                        shape="3, 3")
    INLIERS = Output("one row (keypoint, template keypoint) per inlier match", dynamic=True,
                     capacity="@max_matches, 2")
    RESULT = Output("what was found: " + RESULT_DESCRIPTION, shape=str(RESULT_SIZE))

    def configure(self):
        self.cv2 = opencv()

    def init(self):
        identity(self.HOMOGRAPHY)
        self.RESULT[TEMPLATE] = -1

    def _matches(self):
        """The usable matches, best scores first, as int rows and their scores."""
        matches = rows(self.CORRESPONDENCES, 4, "CORRESPONDENCES")
        matches = matches[np.argsort(-matches[:, 3], kind="stable")][:int(self.max_matches)]
        points = rows(self.KEYPOINTS, 2, "KEYPOINTS")
        stored = rows(self.TEMPLATE_KEYPOINTS, 2, "TEMPLATE_KEYPOINTS")
        index = matches[:, :3].astype(np.int64)
        usable = ((index[:, 1] >= 0) & (index[:, 1] < len(points)) & (index[:, 2] >= 0)
                  & (index[:, 2] < len(stored)))
        return index[usable], matches[usable, 3], points, stored

    def _try(self, template, first, count, corners, index, scores, points, stored):
        """The figures of one template's fit, or None when it has too few matches."""
        mine = (index[:, 0] == template) & (index[:, 2] >= first) & (
            index[:, 2] < first + count)
        if mine.sum() < max(4, self.min_inliers):
            return None
        pairs, score = index[mine, 1:], scores[mine]
        source, target = stored[pairs[:, 1]], points[pairs[:, 0]]
        homography, mask = self.cv2.findHomography(
            source.astype(np.float32), target.astype(np.float32), self.cv2.RANSAC,
            float(self.reprojection_threshold), maxIters=int(self.ransac_iterations))
        if homography is None:
            return None
        inlier = mask.ravel() > 0
        errors = np.linalg.norm(project(homography, source[inlier]) - target[inlier], axis=1)
        outline = corners.reshape(4, 2)
        plausible, area = plausible_polygon(project(homography, outline), self.image_width,
                                            self.image_height, self.min_area_fraction,
                                            self.max_area_fraction)
        hull = self.cv2.convexHull(source[inlier].astype(np.float32)).reshape(-1, 2) \
            if inlier.sum() >= 3 else np.zeros((0, 2))
        coverage = min(1.0, polygon_area(hull) / max(polygon_area(outline), 1e-9)) \
            if len(hull) >= 3 else 0.0
        figures = np.zeros(RESULT_SIZE)
        figures[[TEMPLATE, POINTS, INLIER_RATIO, AREA, COVERAGE]] = (
            template, inlier.sum(), inlier.mean(), area, coverage)
        figures[MEAN_ERROR] = errors.mean() if len(errors) else np.inf
        figures[MEAN_SCORE] = score[inlier].mean() if inlier.any() else 0.0
        figures[FOUND] = float(
            plausible and inlier.sum() >= self.min_inliers
            and figures[INLIER_RATIO] >= self.min_inlier_ratio
            and figures[MEAN_SCORE] >= self.min_mean_match_score
            and coverage >= self.min_source_coverage
            and figures[MEAN_ERROR] <= self.max_mean_error)
        return figures, homography, pairs[inlier]

    def tick(self):
        index, scores, points, stored = self._matches()
        corners = rows(self.TEMPLATE_CORNERS, 8, "TEMPLATE_CORNERS")
        best = None
        for template, (first, count) in enumerate(template_ranges(self.TEMPLATE_RANGES)
                                                  [:min(int(self.max_templates),
                                                        len(corners))]):
            fit = self._try(template, first, count, corners[template], index, scores,
                            points, stored)
            if fit is None or not fit[0][FOUND]:
                continue
            if best is None or (fit[0][POINTS], -fit[0][MEAN_ERROR]) > (
                    best[0][POINTS], -best[0][MEAN_ERROR]):
                best = fit
        if best is None:
            identity(self.HOMOGRAPHY)
            self.RESULT[...] = 0
            self.RESULT[TEMPLATE] = -1
            self.INLIERS.clear()
            return
        figures, homography, inliers = best
        self.HOMOGRAPHY[...] = homography
        self.RESULT[...] = figures
        self.INLIERS.set(inliers)
