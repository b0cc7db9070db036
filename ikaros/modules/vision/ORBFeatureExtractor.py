"""ORBFeatureExtractor: feature points and binary descriptors of an image (OpenCV's ORB)."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import GrayImage, Uint8Image, check_image, opencv
from ._template import flag

DESCRIPTOR_BYTES = 32


class ORBFeatureExtractor(Module):
    """Finds feature points in an image and describes each with OpenCV's ORB (oriented FAST
    corners with rotated BRIEF descriptors, Rublee et al. 2011). This class is not in
    Ikaros 3: it stands in for ALIKEDFeatureExtractor, which runs a neural network from an
    ONNX file, with the same outputs, so the template-tracking classes (TemplateFeatureBank,
    FeatureRegionFilter, FeatureMatcher, RobustTransformEstimator, ...) run on OpenCV alone.
    The image (gray, or colour read as its intensity) is scaled to ``image_width`` x
    ``image_height`` first, the frame in which the points are given (pixels, the centre of
    the top-left pixel at (0, 0)). KEYPOINTS has one row (x, y) per point, strongest first,
    at most ``max_features``; DESCRIPTORS the matching rows of 32 bytes (256 bits) as
    numbers 0..255, compared by Hamming distance (FeatureMatcher's ``norm="hamming"``);
    SCORES each point's corner response (Harris score). While ENABLE is connected and not
    above 0 the lists are empty and the image is not processed."""

    image_width = Parameter(320, "the width of the frame the points are given in (the "
                            "image is scaled to it)", type="int", range=(8, None))
    image_height = Parameter(240, "the height of that frame", type="int", range=(8, None))
    max_features = Parameter(512, "the most points found", type="int", range=(1, None),
                             fixed=True)
    fast_threshold = Parameter(20, "how much brighter or darker than the ring around it a "
                               "corner must be (0..255)", type="int", range=(1, 255))

    INPUT = Input("the image: gray (rows, cols) or colour (3, rows, cols)")
    ENABLE = Input("above 0 (or unconnected) to find points this tick", optional=True)
    KEYPOINTS = Output("one row (x, y) per point, in pixels of the frame", dynamic=True,
                       capacity="@max_features, 2")
    DESCRIPTORS = Output("one row of 32 descriptor bytes (0..255) per point", dynamic=True,
                         capacity=f"@max_features, {DESCRIPTOR_BYTES}")
    SCORES = Output("the corner response of each point", dynamic=True,
                    capacity="@max_features")

    def configure(self):
        self.cv2 = opencv()

    def init(self):
        check_image(self.INPUT.shape)
        self._gray = GrayImage(self.INPUT)
        self._levels = Uint8Image(self.INPUT.shape[-2:])
        self._size = (int(self.image_width), int(self.image_height))

    def tick(self):
        if self.ENABLE is not None and not flag(self.ENABLE):
            for out in (self.KEYPOINTS, self.DESCRIPTORS, self.SCORES):
                out.clear()
            return
        image = self._levels(self._gray())
        if image.shape[::-1] != self._size:
            image = self.cv2.resize(image, self._size, interpolation=self.cv2.INTER_AREA)
        orb = self.cv2.ORB_create(nfeatures=int(self.max_features),
                                  fastThreshold=int(self.fast_threshold))
        keypoints, descriptors = orb.detectAndCompute(image, None)
        if descriptors is None or not keypoints:
            for out in (self.KEYPOINTS, self.DESCRIPTORS, self.SCORES):
                out.clear()
            return
        order = np.argsort([-k.response for k in keypoints], kind="stable")
        order = order[:int(self.max_features)]
        self.KEYPOINTS.set(np.array([keypoints[i].pt for i in order]).reshape(-1, 2))
        self.DESCRIPTORS.set(descriptors[order].astype(np.float32))
        self.SCORES.set(np.array([keypoints[i].response for i in order]))
