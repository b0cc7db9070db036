"""SpatialClustering: positions of clusters of bright pixels, tracked from tick to tick."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import GrayImage, check_image, opencv


class SpatialClustering(Module):
    """Finds up to `no_of_clusters` clusters of pixels above `threshold` in INPUT (a map such
    as ColorClassifier's output; a colour image is used through its intensity). A cluster is
    seeded where most such pixels lie within a square of side 2 · radius + 1, then its centre
    moves to the value-weighted centroid of the pixels within `cluster_radius` of it (a few
    mean-shift steps), and those pixels are removed before the next cluster is sought.
    `cluster_radius` is a fraction of the image width. CONFIDENCE is the cluster's share of
    the summed above-threshold values; a cluster whose sum is below `min_cluster_area` times
    that of the largest cluster is dropped (confidence 0). OUTPUT rows are (x, y) image
    coordinates in 0..1 (x from the left edge, y from the top; pixel (r, c) has its centre
    at ((c + 0.5) / cols, (r + 0.5) / rows)). With `tracking_distance` above 0 each row keeps
    following the cluster it had if one lies within that distance (in 0..1 coordinates),
    and a row without a cluster keeps its last position with confidence 0; with `sorting`
    the rows are instead ordered by confidence, largest first, every tick."""

    no_of_clusters = Parameter(1, "the largest number of clusters", type="int")
    threshold = Parameter(0.1, "pixels above this value belong to clusters")
    cluster_radius = Parameter(0.1, "radius of a cluster as a fraction of the image width")
    min_cluster_area = Parameter(0.2, "smallest cluster, as a fraction of the largest "
                                 "cluster's summed values")
    tracking_distance = Parameter(0.25, "a row follows its cluster if it moved less than "
                                  "this (0..1 coordinates); 0: no tracking")
    sorting = Parameter(False, "order the rows by confidence each tick instead of tracking")

    INPUT = Input("the map: gray (rows, cols) or colour (3, rows, cols)")
    OUTPUT = Output("one row (x, y) per cluster, image coordinates in 0..1",
                    shape="@no_of_clusters, 2")
    CONFIDENCE = Output("each cluster's share of the summed values; 0 for no cluster",
                        shape="@no_of_clusters")

    def configure(self):
        self.cv2 = opencv()
        if self.no_of_clusters < 1:
            raise ValueError("no_of_clusters must be at least 1")

    def init(self):
        check_image(self.INPUT.shape)
        self._gray = GrayImage(self.INPUT)
        rows, cols = self.INPUT.shape[-2:]
        self._size = np.array([cols, rows], np.float64)
        self._r = r = max(1, int(round(self.cluster_radius * cols)))
        yy, xx = np.mgrid[-r:r + 1, -r:r + 1]
        self._disc = (xx * xx + yy * yy <= r * r).astype(np.float32)
        self._yy, self._xx = yy.astype(np.float32), xx.astype(np.float32)
        self._values = np.zeros((rows, cols), np.float32)
        self._mask = np.zeros((rows, cols), np.uint8)
        side = 2 * r + 1                   # counts in a square fit 16 bits up to side 255
        self._depth = self.cv2.CV_16U if side * side <= 65535 else self.cv2.CV_32F
        self._density = np.zeros((rows, cols), np.uint16 if side * side <= 65535 else
                                 np.float32)
        self._tracked = False

    def _window(self, cx, cy):
        """Slices of the image and of the disc for a disc centred at pixel (cx, cy)."""
        r, (rows, cols) = self._r, self._values.shape
        y0, y1 = max(0, cy - r), min(rows, cy + r + 1)
        x0, x1 = max(0, cx - r), min(cols, cx + r + 1)
        return ((slice(y0, y1), slice(x0, x1)),
                (slice(y0 - cy + r, y1 - cy + r), slice(x0 - cx + r, x1 - cx + r)))

    def _find(self):
        """The clusters of this tick: a list of ((x, y) in pixels, summed value)."""
        cv2 = self.cv2
        values, mask = self._values, self._mask
        gray = self._gray()
        np.greater(gray, self.threshold, out=mask, casting="unsafe")
        np.multiply(gray, mask, out=values)
        side = 2 * self._r + 1
        found = []
        for _ in range(self.no_of_clusters):
            source = mask if self._depth == cv2.CV_16U else mask.astype(np.float32)
            cv2.boxFilter(source, self._depth, (side, side), dst=self._density,
                          normalize=False, borderType=cv2.BORDER_CONSTANT)
            _, best, _, (cx, cy) = cv2.minMaxLoc(self._density)
            if best < 0.5:
                break
            # start from the centroid of the pixels in the densest square
            r = self._r
            top, left = max(0, cy - r), max(0, cx - r)
            box = values[top:cy + r + 1, left:cx + r + 1]
            m = cv2.moments(box)
            x, y = left + m["m10"] / m["m00"], top + m["m01"] / m["m00"]
            for _ in range(10):                          # mean shift to the centroid
                image, disc = self._window(int(round(x)), int(round(y)))
                w = values[image] * self._disc[disc]
                total = float(w.sum())
                if total <= 0:
                    break
                nx = float((w * self._xx[disc]).sum()) / total + int(round(x))
                ny = float((w * self._yy[disc]).sum()) / total + int(round(y))
                moved = abs(nx - x) + abs(ny - y)
                x, y = nx, ny
                if moved < 1e-3:
                    break
            image, disc = self._window(int(round(x)), int(round(y)))
            inside = self._disc[disc] > 0
            total = float(values[image][inside].sum())
            if total > 0:
                found.append(((x, y), total))
                values[image][inside] = 0
                mask[image][inside] = 0
            else:                       # scattered pixels: drop the seed square instead
                box[...] = 0
                mask[top:cy + r + 1, left:cx + r + 1] = 0
        return found

    def tick(self):
        found = self._find()
        if found:
            largest = max(t for _, t in found)
            found = [(p, t) for p, t in found if t >= self.min_cluster_area * largest]
        mass = sum(t for _, t in found) or 1.0
        clusters = [((np.array(p) + 0.5) / self._size, t / mass) for p, t in found]
        if self.sorting:
            clusters.sort(key=lambda c: -c[1])
        if self.sorting or self.tracking_distance <= 0 or not self._tracked:
            self.OUTPUT.fill(0)
            self.CONFIDENCE.fill(0)
            for i, (p, c) in enumerate(clusters):
                self.OUTPUT[i], self.CONFIDENCE[i] = p, c
            self._tracked = bool(clusters)
            return
        self._follow(clusters)

    def _follow(self, clusters):
        """Give each row the nearest new cluster within tracking_distance, nearest pairs
        first; clusters left over take the rows left over."""
        previous = self.OUTPUT.astype(np.float64)
        free_rows, free = set(range(len(previous))), set(range(len(clusters)))
        pairs = sorted((float(np.hypot(*(clusters[j][0] - previous[i]))), i, j)
                       for i in free_rows for j in free)
        self.CONFIDENCE.fill(0)
        for d, i, j in pairs:
            if d <= self.tracking_distance and i in free_rows and j in free:
                self.OUTPUT[i], self.CONFIDENCE[i] = clusters[j]
                free_rows.discard(i)
                free.discard(j)
        for i, j in zip(sorted(free_rows), sorted(free)):
            self.OUTPUT[i], self.CONFIDENCE[i] = clusters[j]
