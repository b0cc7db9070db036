"""FeatureMatcher: matches the features of an image to those of every stored template."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import opencv
from ._template import flag, rows, template_ranges


class FeatureMatcher(Module):
    """Matches each template's descriptors (from TemplateFeatureBank) to the descriptors of
    the current image with OpenCV's brute-force matcher: for every template descriptor its
    two nearest image descriptors, kept when the nearest is clearly nearer than the second
    (Lowe's ratio test: distance below ``ratio`` times the second's). This class is not in
    Ikaros 3: it stands in for LightGlueFeatureMatcher (a neural network run from an ONNX
    file) with the same inputs and output, so RobustTransformEstimator runs on OpenCV's
    features. CORRESPONDENCES has one row (template, keypoint, template keypoint, score)
    per match: the template's index, the row of KEYPOINTS and the row of
    TEMPLATE_KEYPOINTS, and a score 0..1 (1 - distance / largest distance: the number of
    descriptor bits for ``hamming``, 2 for ``l2``, the largest distance of unit vectors);
    at most ``max_matches_per_template`` of the best matches per template and the first
    ``max_templates`` templates. Use ``hamming`` with ORBFeatureExtractor's binary
    descriptors (bytes 0..255) and ``l2`` with real-valued unit descriptors such as
    ALIKED's. While ENABLE is connected and not above 0 nothing is matched."""

    max_templates = Parameter(16, "the most templates matched", type="int", range=(1, None),
                              fixed=True)
    max_matches_per_template = Parameter(512, "the most matches kept per template",
                                         type="int", range=(1, None), fixed=True)
    ratio = Parameter(0.8, "a match is kept when its distance is below ratio times the "
                      "second nearest's", range=(0, 1))
    norm = Parameter("hamming", "how descriptors are compared: hamming for bytes (ORB), "
                     "l2 for real-valued descriptors", options="hamming/l2")

    KEYPOINTS = Input("the image's points, one row (x, y) per point")
    DESCRIPTORS = Input("the image's descriptors, one row per point")
    TEMPLATE_KEYPOINTS = Input("the templates' points (TemplateFeatureBank)")
    TEMPLATE_DESCRIPTORS = Input("the templates' descriptors, one row per point")
    TEMPLATE_RANGES = Input("one row (first, count) per template")
    ENABLE = Input("above 0 (or unconnected) to match this tick", optional=True)
    CORRESPONDENCES = Output("one row (template, keypoint, template keypoint, score) per "
                             "match", dynamic=True,
                             capacity="@max_templates * @max_matches_per_template, 4")

    def configure(self):
        self.cv2 = opencv()

    def _descriptors(self, array, count):
        values = np.asarray(array, np.float32)
        values = values.reshape(len(values), -1) if values.size else values.reshape(0, 1)
        values = values[:count]
        if self.norm == "hamming":
            return np.clip(np.rint(values), 0, 255).astype(np.uint8)
        return values

    def tick(self):
        self.CORRESPONDENCES.clear()
        if self.ENABLE is not None and not flag(self.ENABLE):
            return
        count = len(rows(self.KEYPOINTS, 2, "KEYPOINTS"))
        image = self._descriptors(self.DESCRIPTORS, count)
        stored = len(rows(self.TEMPLATE_KEYPOINTS, 2, "TEMPLATE_KEYPOINTS"))
        templates = self._descriptors(self.TEMPLATE_DESCRIPTORS, stored)
        if len(image) < 2 or not len(templates):
            return
        if image.shape[1] != templates.shape[1]:
            raise ValueError(f"DESCRIPTORS have {image.shape[1]} values and "
                             f"TEMPLATE_DESCRIPTORS {templates.shape[1]}: they must be of "
                             f"the same kind")
        hamming = self.norm == "hamming"
        largest = 8.0 * image.shape[1] if hamming else 2.0
        matcher = self.cv2.BFMatcher(self.cv2.NORM_HAMMING if hamming else self.cv2.NORM_L2)
        found = []
        for t, (first, n) in enumerate(template_ranges(self.TEMPLATE_RANGES)
                                       [:int(self.max_templates)]):
            first, last = max(first, 0), min(first + n, len(templates))
            if last <= first:
                continue
            pairs = matcher.knnMatch(templates[first:last], image, k=2)
            kept = [(m.distance, m.trainIdx, first + m.queryIdx) for m, *rest in
                    (p for p in pairs if p)
                    if rest and m.distance < self.ratio * rest[0].distance]
            kept.sort()
            for distance, keypoint, template_point in kept[:int(self.max_matches_per_template)]:
                found.append((t, keypoint, template_point, max(0.0, 1 - distance / largest)))
        if found:
            self.CORRESPONDENCES.set(np.array(found))
