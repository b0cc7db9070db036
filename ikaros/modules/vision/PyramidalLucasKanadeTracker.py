"""PyramidalLucasKanadeTracker: follows a found template from image to image by optical flow."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import GrayImage, Uint8Image, check_image, opencv
from ._template import (AREA, COVERAGE, FOUND, INLIER_RATIO, MEAN_ERROR, MEAN_SCORE, POINTS,
                        RESULT_DESCRIPTION, RESULT_SIZE, TEMPLATE, found, identity,
                        polygon_area, project, rows, template_ranges)

RANSAC_THRESHOLD = 3.0     # pixels: a tracked point further from the fitted homography is dropped


class PyramidalLucasKanadeTracker(Module):
    """Keeps a template found once (by RobustTransformEstimator) in view between detections
    by following its points with pyramidal Lucas-Kanade optical flow (Bouguet's method,
    OpenCV's calcOpticalFlowPyrLK: ``levels`` pyramid levels, a window of
    2 ``window_radius`` + 1 pixels, at most ``iterations`` iterations per level).

    Seeding: on a tick where SEED_RESULT says found, the seed's inlier matches (SEED_INLIERS,
    rows (keypoint, template keypoint) into KEYPOINTS and TEMPLATE_KEYPOINTS, those of the
    seed's template by TEMPLATE_RANGES) become the tracked points, at most ``max_points``:
    their template positions (REFERENCE_POINTS) and their positions in this image
    (CURRENT_POINTS), and TRANSFORM takes SEED_HOMOGRAPHY. While tracking, a seed is taken
    only when it agrees with the tracked transform, the seed's points lying on average
    within ``max_reseed_displacement`` pixels of where the tracked transform puts them (a
    detection far from a good track is taken for a false one).

    Tracking: every point is followed from the last image to this one and back again; it is
    kept when both succeed, it comes back within ``forward_backward_threshold`` pixels of
    where it started, and its mean absolute intensity difference over the window (0..1) is at
    most ``max_residual``. The homography from the kept points' template positions to their
    new positions is fitted with RANSAC (3 pixels), and its inliers stay tracked. With fewer
    than ``min_points`` left the target is lost (RESULT found 0, no points) until the next
    seed. RESULT is (found, template, points, points kept this tick as a share of those
    before, mean forward-backward error in pixels, 1 - mean residual (on the tick a seed is
    taken: the seed's mean score), area of the points' convex hull as a share of the frame,
    points as a share of those seeded): the same 8 values as RobustTransformEstimator's
    RESULT, so that TemplateTrackingController can weigh both. IMAGE is scaled to the
    ``image_width`` x ``image_height`` frame of the points.
    The behaviour is this project's reading of the Ikaros 3 interface
    (docs/vision-tracking.md)."""

    image_width = Parameter(320, "the width of the frame the points are given in (IMAGE is "
                            "scaled to it)", type="int", range=(8, None))
    image_height = Parameter(240, "the height of that frame", type="int", range=(8, None))
    levels = Parameter(3, "the number of pyramid levels", type="int", range=(1, 10))
    window_radius = Parameter(3, "the half-width of the window matched around each point, "
                              "in pixels", type="int", range=(1, None))
    iterations = Parameter(10, "the most iterations per pyramid level", type="int",
                           range=(1, None))
    max_residual = Parameter(0.08, "the largest mean absolute difference (0..1) between a "
                             "point's window in the two images", range=(0, None))
    forward_backward_threshold = Parameter(1.5, "the largest distance in pixels between a "
                                           "point and where tracking it forward and back "
                                           "brings it", range=(0, None))
    min_points = Parameter(6, "the fewest points that keep the target tracked", type="int",
                           range=(4, None))
    max_points = Parameter(512, "the most points tracked", type="int", range=(4, None),
                           fixed=True)
    max_reseed_displacement = Parameter(20.0, "while tracking, the largest mean distance in "
                                        "pixels between a seed and the tracked transform for "
                                        "the seed to be taken", range=(0, None))

    IMAGE = Input("the image: gray (rows, cols) or colour (3, rows, cols)")
    KEYPOINTS = Input("the image's points, one row (x, y) each (SEED_INLIERS index them)")
    TEMPLATE_KEYPOINTS = Input("the templates' points (TemplateFeatureBank)")
    TEMPLATE_RANGES = Input("one row (first, count) per template")
    SEED_HOMOGRAPHY = Input("a detection's transform (RobustTransformEstimator.HOMOGRAPHY)",
                            size="3, 3")
    SEED_RESULT = Input("a detection's RESULT")
    SEED_INLIERS = Input("a detection's INLIERS: rows (keypoint, template keypoint)")
    TRANSFORM = Output("the tracked 3 x 3 transform from template points to the image",
                       shape="3, 3")
    REFERENCE_POINTS = Output("the tracked points' template positions, one row (x, y) each",
                              dynamic=True, capacity="@max_points, 2")
    CURRENT_POINTS = Output("the tracked points' positions in this image", dynamic=True,
                            capacity="@max_points, 2")
    RESULT = Output("the tracking result: " + RESULT_DESCRIPTION, shape=str(RESULT_SIZE))

    def configure(self):
        self.cv2 = opencv()

    def init(self):
        check_image(self.IMAGE.shape, "IMAGE")
        self._gray = GrayImage(self.IMAGE)
        self._levels = Uint8Image(self.IMAGE.shape[-2:])
        self._size = (int(self.image_width), int(self.image_height))
        self._previous = None
        self._seeded = 0
        identity(self.TRANSFORM)
        self.RESULT[TEMPLATE] = -1

    def _image(self):
        image = self._levels(self._gray())
        if image.shape[::-1] != self._size:
            image = self.cv2.resize(image, self._size, interpolation=self.cv2.INTER_AREA)
        return image

    def _flow(self, start, end, points):
        cv2 = self.cv2
        criteria = (cv2.TERM_CRITERIA_COUNT | cv2.TERM_CRITERIA_EPS, int(self.iterations), 0.01)
        side = 2 * int(self.window_radius) + 1
        moved, status, error = cv2.calcOpticalFlowPyrLK(
            start, end, points.astype(np.float32).reshape(-1, 1, 2), None,
            winSize=(side, side), maxLevel=int(self.levels) - 1, criteria=criteria)
        return moved.reshape(-1, 2).astype(np.float64), status.ravel() > 0, error.ravel()

    def _lose(self):
        self.REFERENCE_POINTS.clear()
        self.CURRENT_POINTS.clear()
        self.RESULT[...] = 0
        self.RESULT[TEMPLATE] = -1

    def _track(self, image):
        reference, current = np.asarray(self.REFERENCE_POINTS), np.asarray(
            self.CURRENT_POINTS)
        before = len(current)
        ahead, ok_ahead, residual = self._flow(self._previous, image, current)
        back, ok_back, _ = self._flow(image, self._previous, ahead)
        drift = np.linalg.norm(back - current, axis=1)
        keep = (ok_ahead & ok_back & (drift <= self.forward_backward_threshold)
                & (residual / 255.0 <= self.max_residual))
        if keep.sum() < self.min_points:
            return self._lose()
        homography, mask = self.cv2.findHomography(
            reference[keep].astype(np.float32), ahead[keep].astype(np.float32),
            self.cv2.RANSAC, RANSAC_THRESHOLD)
        if homography is None:
            return self._lose()
        kept = np.flatnonzero(keep)[mask.ravel() > 0]
        if len(kept) < self.min_points:
            return self._lose()
        self.REFERENCE_POINTS.set(reference[kept])
        self.CURRENT_POINTS.set(ahead[kept])
        self.TRANSFORM[...] = homography
        self.RESULT[[FOUND, POINTS, INLIER_RATIO, MEAN_ERROR, MEAN_SCORE, AREA, COVERAGE]] = (
            1, len(kept), len(kept) / before, drift[kept].mean(),
            1 - residual[kept].mean() / 255.0, self._hull_fraction(ahead[kept]),
            len(kept) / max(self._seeded, 1))

    def _hull_fraction(self, points):
        """The area of the points' convex hull as a share of the frame."""
        hull = self.cv2.convexHull(points.astype(np.float32)).reshape(-1, 2)
        return polygon_area(hull) / (self._size[0] * self._size[1])

    def _seed(self):
        """The seed's (template, reference points, current points), or None."""
        if not found(self.SEED_RESULT):
            return None
        template = int(np.asarray(self.SEED_RESULT).ravel()[TEMPLATE])
        pairs = rows(self.SEED_INLIERS, 2, "SEED_INLIERS").astype(np.int64)
        points = rows(self.KEYPOINTS, 2, "KEYPOINTS")
        stored = rows(self.TEMPLATE_KEYPOINTS, 2, "TEMPLATE_KEYPOINTS")
        usable = ((pairs[:, 0] >= 0) & (pairs[:, 0] < len(points)) & (pairs[:, 1] >= 0)
                  & (pairs[:, 1] < len(stored)))
        ranges = template_ranges(self.TEMPLATE_RANGES)
        if 0 <= template < len(ranges):
            first, count = ranges[template]
            usable &= (pairs[:, 1] >= first) & (pairs[:, 1] < first + count)
        pairs = pairs[usable][:int(self.max_points)]
        if len(pairs) < self.min_points:
            return None
        return template, stored[pairs[:, 1]], points[pairs[:, 0]]

    def tick(self):
        image = self._image()
        tracking = bool(self.RESULT[FOUND] > 0)
        if tracking and self._previous is not None:
            self._track(image)
            tracking = bool(self.RESULT[FOUND] > 0)
        seed = self._seed()
        if seed is not None:
            template, reference, current = seed
            homography = np.asarray(self.SEED_HOMOGRAPHY, np.float64).reshape(3, 3)
            if tracking:
                displacement = np.linalg.norm(project(self.TRANSFORM, reference) - current,
                                              axis=1).mean()
                take = displacement <= self.max_reseed_displacement
            else:
                take = True
            if take:
                self.REFERENCE_POINTS.set(reference)
                self.CURRENT_POINTS.set(current)
                self.TRANSFORM[...] = homography
                self._seeded = len(reference)
                given = np.asarray(self.SEED_RESULT).ravel()
                score = given[MEAN_SCORE] if given.size > MEAN_SCORE else 0.0
                self.RESULT[...] = (1, template, len(reference), 1, 0, score,
                                    self._hull_fraction(current), 1)
        self._previous = image.copy()        # the converter writes one buffer each tick
