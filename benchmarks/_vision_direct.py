"""The vision benchmark's reference: the six stages of its model called directly in OpenCV
and NumPy on arrays made once, computing what the modules compute (``check`` in vision.py
compares the two, value for value).

* colour transform: ``cv2.add`` twice (I = R + G + B), ``cv2.divide`` twice (r = R / I,
  g = G / I), and 1/3 where I is 0 (``cv2.countNonZero`` tells);
* Gaussian filter: for each of the three planes ``cv2.sepFilter2D`` with the 5-tap kernel
  of ``cv2.getGaussianKernel(5, 1, CV_32F)`` into a buffer, then the part where the kernel
  fits copied out (kernel size - 1 rows and columns smaller, as the module);
* classifier: ColorClassifier's test on every pixel in float32, one NumPy call a step:
  dr = r - 1/3, dg = g - 1/3, the saturation ``np.hypot`` (the float32 hypot the class
  uses; ``cv2.magnitude`` rounds differently), d . u >= |d| cos(width) and the two strict
  saturation bounds, into a 0/1 map;
* dilate: ``cv2.dilate`` with a 3 x 3 square, the valid part copied out;
* clustering: the pixels above the threshold (``np.greater``, ``np.flatnonzero``) and
  SpatialClustering's raster-order clustering (``raster_clusters``, the function the
  module calls; OpenCV has no such clustering), the kept cluster's centroid as a fraction
  of the map; the overlay gets the previous frame's, as the module gives it;
* overlay: the image copied and a circle drawn on each plane with ``cv2.circle``.
"""
from __future__ import annotations

import cv2
import numpy as np

from ikaros.modules.vision._clustering import raster_clusters

# the model's parameters (vision.py's MODEL)
HUE, WIDTH, SATURATION = 117.0, 15.0, (0.05, 0.5)
THRESHOLD, RADIUS, AREA = 0.5, 0.05, 0.001


class DirectPipeline:
    """The six stages on preallocated arrays; ``stages()`` lists them in order."""

    def __init__(self, rows: int, cols: int):
        self.rows, self.cols = rows, cols
        shape, inner, dilated = (rows, cols), (rows - 4, cols - 4), (rows - 6, cols - 6)
        self.rgi = np.zeros((3,) + shape, np.float32)
        self.full = np.zeros(shape, np.float32)
        self.blur = np.zeros((3,) + inner, np.float32)
        self.kernel = cv2.getGaussianKernel(5, 1.0, cv2.CV_32F)
        self.dr, self.dg, self.saturation, self.along, self.limit = (
            np.zeros(inner, np.float32) for _ in range(5))
        self.selected, self.test = np.zeros(inner, bool), np.zeros(inner, bool)
        self.classified = np.zeros(inner, np.float32)
        self.dilated_full = np.zeros(inner, np.float32)
        self.dilated = np.zeros(dilated, np.float32)
        self.above = np.zeros(dilated, bool)
        self.square = np.ones((3, 3), np.uint8)
        hue, width = np.radians(HUE), np.radians(WIDTH)
        self.sin_c, self.cos_c = np.float32(np.sin(hue)), np.float32(np.cos(hue))
        self.cos_width = np.float32(np.cos(width))
        self.map_size = np.array([dilated[1], dilated[0]], np.float64)
        self.radius2 = (RADIUS * self.map_size[0]) ** 2
        self.positions = np.zeros((1, 2), np.float32)   # this frame's cluster
        self.shown = np.zeros((1, 2), np.float32)       # the previous frame's
        self.overlay = np.zeros((3,) + shape, np.float32)

    def colour_transform(self, image):
        red, green, blue = image
        total = self.rgi[2]
        cv2.add(red, green, dst=total)
        cv2.add(total, blue, dst=total)
        cv2.divide(red, total, dst=self.rgi[0])
        cv2.divide(green, total, dst=self.rgi[1])
        if cv2.countNonZero(total) < total.size:
            zero = total == 0
            self.rgi[0][zero] = self.rgi[1][zero] = 1.0 / 3.0

    def gaussian(self, image):
        for src, dst in zip(self.rgi, self.blur):
            cv2.sepFilter2D(src, -1, self.kernel, self.kernel, dst=self.full,
                            borderType=cv2.BORDER_REFLECT)
            dst[...] = self.full[2:-2, 2:-2]

    def classifier(self, image):
        dr, dg, saturation, along, limit = (self.dr, self.dg, self.saturation, self.along,
                                            self.limit)
        np.subtract(self.blur[0], 1.0 / 3.0, out=dr)
        np.subtract(self.blur[1], 1.0 / 3.0, out=dg)
        np.hypot(dr, dg, out=saturation)
        np.multiply(dr, self.sin_c, out=along)
        np.multiply(dg, self.cos_c, out=limit)
        np.add(along, limit, out=along)
        np.multiply(saturation, self.cos_width, out=limit)
        np.greater_equal(along, limit, out=self.selected)
        np.greater(saturation, SATURATION[0], out=self.test)
        self.selected &= self.test
        np.less(saturation, SATURATION[1], out=self.test)
        self.selected &= self.test
        np.copyto(self.classified, self.selected)

    def dilate(self, image):
        cv2.dilate(self.classified, self.square, dst=self.dilated_full)
        self.dilated[...] = self.dilated_full[1:-1, 1:-1]

    def clustering(self, image):
        np.copyto(self.shown, self.positions)
        np.greater(self.dilated, THRESHOLD, out=self.above)
        rows, cols = np.divmod(np.flatnonzero(self.above), self.above.shape[1])
        least = AREA * self.map_size.prod()
        for sx, sy, n in raster_clusters(rows, cols, self.radius2, 1):
            if n > least:
                self.positions[0] = np.array([sx / n, sy / n]) / self.map_size

    def overlay_stage(self, image):
        np.copyto(self.overlay, image)
        x, y = self.shown[0]
        for plane in self.overlay:
            cv2.circle(plane, (int(x * self.cols), int(y * self.rows)), 20, 1.0, 2)

    def stages(self):
        return [("colour transform", self.colour_transform), ("Gaussian filter", self.gaussian),
                ("classifier", self.classifier), ("dilate", self.dilate),
                ("clustering", self.clustering), ("overlay", self.overlay_stage)]

    def results(self) -> dict:
        """Each stage's result under the name of the model's output that holds it."""
        return {"Chromaticity.OUTPUT": self.rgi, "BlurR.OUTPUT": self.blur[0],
                "BlurG.OUTPUT": self.blur[1], "BlurI.OUTPUT": self.blur[2],
                "Classifier.OUTPUT": self.classified, "Dilate.OUTPUT": self.dilated,
                "Clustering.OUTPUT": self.shown, "Overlay.OUTPUT": self.overlay}
