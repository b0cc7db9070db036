"""The face detector shared by CIFaceDetector and DFaceDetector: OpenCV's LBP frontal-face
cascade, the copy that ships inside scikit-image, run by scikit-image's cascade detector."""
from __future__ import annotations

import numpy as np

from ikaros.module import Input, Module, Output, Parameter, require

from ._cv import GrayImage, check_image


class FaceDetectorBase(Module):
    """Detects frontal faces and writes their positions, sizes and bounds."""

    max_faces = Parameter(10, "the largest number of faces reported", type="int")
    INPUT = Input("the image: gray (rows, cols) or colour (3, rows, cols)")
    FACE_POSITION = Output("the centre (x, y) of each face in 0..1", shape="@max_faces, 2")
    FACE_SIZE = Output("the width and height of each face as fractions of the image's",
                       shape="@max_faces, 2")
    FACE_BOUNDS = Output("the corners (x, y) of each face's box, clockwise from the "
                         "top-left, in 0..1", shape="@max_faces, 8")
    FACE_COUNT = Output("the number of faces found", size="1")

    smallest_face = 0.1       # of the image's shorter side

    def configure(self):
        feature = require("skimage.feature", "scikit-image", extra="vision")
        data = require("skimage.data", "scikit-image", extra="vision")
        if self.max_faces < 1:
            raise ValueError("max_faces must be at least 1")
        self._cascade = feature.Cascade(data.lbp_frontal_face_cascade_filename())

    def init(self):
        check_image(self.INPUT.shape)
        rows, cols = self.INPUT.shape[-2:]
        self._scale = np.array([cols, rows], np.float64)
        self._gray = GrayImage(self.INPUT)

    def detect(self) -> np.ndarray:
        """Boxes (x0, y0, x1, y1) in pixels of the faces found, largest first."""
        gray = self._gray()
        side = min(gray.shape)
        smallest = max(24, int(self.smallest_face * side))
        found = self._cascade.detect_multi_scale(
            img=np.clip(gray, 0, 1), scale_factor=1.2, step_ratio=1,
            min_size=(smallest, smallest), max_size=(side, side))
        boxes = np.array([(f["c"], f["r"], f["c"] + f["width"], f["r"] + f["height"])
                          for f in found], np.float64).reshape(-1, 4)
        order = np.argsort(-(boxes[:, 2] - boxes[:, 0]), kind="stable")
        return boxes[order][:self.max_faces]

    def write_faces(self, boxes: np.ndarray) -> None:
        """Write positions, sizes, bounds and the count for boxes in pixels."""
        for out in (self.FACE_POSITION, self.FACE_SIZE, self.FACE_BOUNDS):
            out.fill(0)
        n = len(boxes)
        self.FACE_COUNT[0] = n
        if not n:
            return
        x0, y0, x1, y1 = (boxes / np.tile(self._scale, 2)).T
        self.FACE_POSITION[:n] = np.stack([(x0 + x1) / 2, (y0 + y1) / 2], axis=1)
        self.FACE_SIZE[:n] = np.stack([x1 - x0, y1 - y0], axis=1)
        self.FACE_BOUNDS[:n] = np.stack([x0, y0, x1, y0, x1, y1, x0, y1], axis=1)


def overlap(a: np.ndarray, b: np.ndarray) -> float:
    """Intersection over union of two boxes (x0, y0, x1, y1)."""
    w = min(a[2], b[2]) - max(a[0], b[0])
    h = min(a[3], b[3]) - max(a[1], b[1])
    if w <= 0 or h <= 0:
        return 0.0
    inter = w * h
    return inter / ((a[2] - a[0]) * (a[3] - a[1]) + (b[2] - b[0]) * (b[3] - b[1]) - inter)
