"""HysteresisThresholding: strong edges and the weak edges reached from them."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import as_image, image_shape, opencv, warn_one_row


class HysteresisThresholding(Module):
    """Hysteresis thresholding of an edge image: OUTPUT is 1 on strong pixels (above
    ``T2``) and on the weak pixels (above ``T1``) they reach, 0 elsewhere; made anew every
    tick.

    ``method="scan"`` (the default) computes as Ikaros 2 does (its golden outputs fit this
    exactly): ``iterations`` times, the inner pixels (``range`` or more pixels from every
    edge) are visited in raster order (rows from the top, each from the left); a visited
    pixel that is strong or already marked marks every weak pixel of the square of side
    2·range + 1 around it (itself included). A mark made ahead of the scan is visited
    in the same pass, so a weak edge can be followed far along the scan's direction in one
    pass but only ``range`` pixels against it; pixels of the border are marked but never
    spread marks, and a strong pixel of the border that nothing reaches stays 0. (Computed
    row by row, vectorised along each row.)

    ``method="dilation"`` (this project's option, independent of the order): the marks
    grow ``iterations`` times by a square of side 2·range + 1 into the weak pixels,
    starting from all strong pixels, borders included. A vector is a one-row image (with
    the default method its output is 0, as in the original)."""

    range = Parameter(1, "how far (pixels) a marked pixel reaches")
    iterations = Parameter(1, "how many passes (scan) or growth steps (dilation)")
    T1 = Parameter(0.3, "weak threshold")
    T2 = Parameter(0.6, "strong threshold")
    method = Parameter("scan", "scan: the original's raster passes; dilation: symmetric "
                       "growth", options="scan/dilation")
    INPUT = Input("the edge image (rows, cols), or a vector (one row)")
    OUTPUT = Output("1 on the kept edges, 0 elsewhere", shape="INPUT.shape")

    def configure(self):
        self.cv2 = opencv()

    def init(self):
        image_shape(self.INPUT.shape, gray=True)
        self._image, self._out = as_image(self.INPUT), as_image(self.OUTPUT)
        shape = self._image.shape
        self._strong = np.zeros(shape, bool)
        self._weak = np.zeros(shape, bool)
        self._kept = np.zeros(shape, np.uint8)
        if self.method == "scan" and self.range >= 0:
            warn_one_row(self, result="it has no inner pixels and the output is always 0")

    def tick(self):
        np.greater(self._image, self.T2, out=self._strong)
        np.greater(self._image, self.T1, out=self._weak)
        if self.method == "scan":
            self._scan()
            return
        kept, weak = self._kept, self._weak.view(np.uint8)
        np.copyto(kept, self._strong, casting="unsafe")
        square = np.ones((2 * self.range + 1,) * 2, np.uint8)
        for _ in range(self.iterations):
            self.cv2.dilate(kept, square, dst=kept)
            np.bitwise_and(kept, weak, out=kept)
        np.copyto(self._out, kept)

    def _scan(self):
        r, strong, weak = int(self.range), self._strong, self._weak
        rows, cols = strong.shape
        marked = np.zeros((rows, cols), bool)
        if r >= 0 and rows > 2 * r and cols > 2 * r:
            seed = np.zeros(cols, bool)
            for _ in range(self.iterations):
                for j in range(r, rows - r):
                    np.logical_or(strong[j], marked[j], out=seed)
                    if not seed[r:cols - r].any():
                        continue
                    fired = _fired(seed, weak[j], r)
                    if fired.size:
                        reach = _reach(fired, r, cols)
                        for row in range(max(j - r, 0), min(j + r + 1, rows)):
                            marked[row] |= reach & weak[row]
        np.copyto(self._out, marked)


def _fired(seed: np.ndarray, weak: np.ndarray, r: int) -> np.ndarray:
    """The columns of one row that spread marks in a raster pass: among its inner columns,
    each seed (strong or marked when visited) and each weak pixel within r columns right of
    a column that fired."""
    cols = seed.size
    inner = slice(r, cols - r)
    candidates = np.flatnonzero(seed[inner] | weak[inner]) + r
    if candidates.size == 0:
        return candidates
    seeds = seed[candidates].astype(np.int64)
    # runs of candidates less than r + 1 apart: inside a run, all from its first seed fire
    run = np.cumsum(np.concatenate(([1], np.diff(candidates) > r)))
    before = np.cumsum(seeds) - seeds
    first = np.flatnonzero(np.concatenate(([True], run[1:] != run[:-1])))
    seen = np.cumsum(seeds) - before[first][run - 1]
    return candidates[seen > 0]


def _reach(fired: np.ndarray, r: int, cols: int) -> np.ndarray:
    """The columns within r of any fired column."""
    edges = np.bincount(np.maximum(fired - r, 0), minlength=cols + 1) - \
        np.bincount(np.minimum(fired + r + 1, cols), minlength=cols + 1)
    return np.cumsum(edges[:cols]) > 0
