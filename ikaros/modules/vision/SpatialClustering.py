"""SpatialClustering: positions of clusters of bright pixels, tracked from tick to tick."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._clustering import raster_clusters
from ._cv import GrayImage, as_image, image_shape


class SpatialClustering(Module):
    """Finds up to ``no_of_clusters`` clusters of the pixels above ``threshold`` in INPUT (a
    map such as ColorClassifier's output; a colour image is used through its intensity, a
    vector is a one-row image). The pixels are visited in raster order (row by row from the
    top, each row from the left). A pixel joins the nearest cluster whose running centroid
    (the mean (column, row) of the pixels it has so far) lies within r = ``cluster_radius``
    · cols pixels of it (distance r included), or else starts a new cluster; once
    ``no_of_clusters`` clusters exist, such a pixel starts the last cluster anew at itself
    (what Ikaros 2's golden outputs show for one cluster: of isolated pixels the last one
    is the cluster). A cluster is kept only when it has more than ``min_cluster_area`` ·
    rows · cols pixels (a fraction of the image). Its CONFIDENCE is count / (2π r²) (as the
    golden outputs show: one pixel with r = 0.4 gives 0.9947), at most 1; rows without a
    cluster have confidence 0 on every tick. OUTPUT rows are the centroids as (x, y) =
    (column / cols, row / rows), fractions of the image's width and height measured to the
    top-left corner of the pixels (the golden outputs: column 3 of 4 gives x = 0.75). As
    in Ikaros 2, OUTPUT shows the positions of the previous tick's clusters: it is a tick
    late behind CONFIDENCE (the golden outputs show it; a defect), and ``positions="current"``
    (this project's correction) shows this tick's. With ``tracking_distance`` above 0 each
    row keeps following the cluster it had if one lies within that distance (in those
    fractions), and a row without a cluster keeps its last position; with ``sorting`` the
    rows are instead ordered by confidence, largest first, every tick. (Not shown by the
    golden files, so this module's reading: the clustering with several clusters, the cap
    of 1 on the confidence, and the tracking and sorting rules.)"""

    no_of_clusters = Parameter(1, "the largest number of clusters", type="int")
    threshold = Parameter(0.1, "pixels above this value belong to clusters")
    cluster_radius = Parameter(0.1, "how far a pixel may lie from a cluster's centroid, as "
                               "a fraction of the image width")
    min_cluster_area = Parameter(0.2, "a cluster needs more pixels than this fraction of "
                                 "the image's pixels")
    tracking_distance = Parameter(0.25, "a row follows its cluster if it moved less than "
                                  "this (fractions of width and height); 0: no tracking")
    sorting = Parameter(False, "order the rows by confidence each tick instead of tracking")
    positions = Parameter("previous", "previous: OUTPUT shows the previous tick's clusters, "
                          "as the original (a defect); current: this tick's",
                          options="previous/current")

    INPUT = Input("the map: gray (rows, cols) or colour (3, rows, cols)")
    OUTPUT = Output("one row (x, y) per cluster, fractions of width and height",
                    shape="@no_of_clusters, 2")
    CONFIDENCE = Output("each cluster's pixel count / (2 pi r²), at most 1; 0 for no "
                        "cluster", shape="@no_of_clusters")

    def configure(self):
        if self.no_of_clusters < 1:
            raise ValueError("no_of_clusters must be at least 1")

    def init(self):
        image = as_image(self.INPUT)
        image_shape(self.INPUT.shape)
        self._gray = GrayImage(image)
        rows, cols = image.shape[-2:]
        self._size = np.array([cols, rows], np.float64)
        self._tracked = False
        self._positions = np.zeros(self.OUTPUT.shape, np.float32)
        self._above = np.zeros((rows, cols), bool)

    def _find(self) -> list[tuple[np.ndarray, int]]:
        """The kept clusters of this tick: ((column, row) centroid in pixels, count)."""
        np.greater(self._gray(), self.threshold, out=self._above)
        rows, cols = np.divmod(np.flatnonzero(self._above), self._above.shape[1])
        radius2 = (self.cluster_radius * self._size[0]) ** 2
        sums = raster_clusters(rows, cols, radius2, self.no_of_clusters)
        least = self.min_cluster_area * self._size.prod()
        return [(np.array([sx / n, sy / n]), n) for sx, sy, n in sums if n > least]

    def tick(self):
        if self.positions == "previous":
            np.copyto(self.OUTPUT, self._positions)
        area = 2.0 * np.pi * (self.cluster_radius * self._size[0]) ** 2
        clusters = [(p / self._size, min(n / area, 1.0) if area > 0 else 1.0)
                    for p, n in self._find()]
        if self.sorting:
            clusters.sort(key=lambda c: -c[1])
        if self.sorting or self.tracking_distance <= 0 or not self._tracked:
            self._positions.fill(0)
            self.CONFIDENCE.fill(0)
            for i, (p, c) in enumerate(clusters):
                self._positions[i], self.CONFIDENCE[i] = p, c
            self._tracked = bool(clusters)
        else:
            self._follow(clusters)
        if self.positions == "current":
            np.copyto(self.OUTPUT, self._positions)

    def _follow(self, clusters):
        """Give each row the nearest new cluster within tracking_distance, nearest pairs
        first; clusters left over take the rows left over."""
        previous = self._positions.astype(np.float64)
        free_rows, free = set(range(len(previous))), set(range(len(clusters)))
        pairs = sorted((float(np.hypot(*(clusters[j][0] - previous[i]))), i, j)
                       for i in free_rows for j in free)
        self.CONFIDENCE.fill(0)
        for d, i, j in pairs:
            if d <= self.tracking_distance and i in free_rows and j in free:
                self._positions[i], self.CONFIDENCE[i] = clusters[j]
                free_rows.discard(i)
                free.discard(j)
        for i, j in zip(sorted(free_rows), sorted(free)):
            self._positions[i], self.CONFIDENCE[i] = clusters[j]
