"""DepthHistogram: the distribution of depths, and the nearest object in it."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class DepthHistogram(Module):
    """Counts the depths of INPUT in `size` equal bins from `min` to `max` (depths at or
    below min, such as 0 for no reading, and at or above max are left out). The first bin
    is never counted: in Ikaros 2's golden outputs every depth fell in it (depths of -1 to
    2 with the default 16 per bin) and the histogram stayed 0; leaving the first bin out
    (where missing readings fall) is this module's reading of those cases, which do not
    show the rest: the bins, the filter and OBJECT below are from the reference's prose.
    With `filter` the counts are smoothed with the kernel (1 2 1) / 4. The nearest object
    is the first bin, counting from min, whose count is above `threshold`, together with
    the bins that follow it while they stay above threshold: OBJECT is (nearest depth,
    farthest depth, number of pixels) of those bins, or 0 0 0 when no bin is above
    threshold. DepthSegmentation cuts the object out with it."""

    min = Parameter(0.0, "the smallest depth counted (excluded)")
    max = Parameter(2048.0, "the largest depth counted (excluded)")
    size = Parameter(128, "the number of bins", type="int")
    filter = Parameter(True, "smooth the histogram with (1 2 1) / 4")
    threshold = Parameter(1000.0, "a bin with more pixels than this holds an object")
    INPUT = Input("the depth image")
    OUTPUT = Output("the number of pixels in each bin", size_param="size")
    OBJECT = Output("(nearest depth, farthest depth, pixels) of the nearest object", size="3")

    def init(self):
        if self.size < 1 or not self.max > self.min:
            raise ValueError("size must be at least 1 and max above min")

    def tick(self):
        d = self.INPUT.ravel()
        d = d[(d > self.min) & (d < self.max)]
        counts = np.bincount(((d - self.min) * (self.size / (self.max - self.min))).astype(
            np.int64), minlength=self.size)[:self.size].astype(np.float32)
        counts[0] = 0.0
        if self.filter and self.size > 2:
            padded = np.pad(counts, 1, mode="edge")
            counts = 0.25 * padded[:-2] + 0.5 * padded[1:-1] + 0.25 * padded[2:]
        self.OUTPUT[...] = counts
        above = np.flatnonzero(counts > self.threshold)
        self.OBJECT.fill(0)
        if len(above):
            first = above[0]
            gaps = np.flatnonzero(counts[first:] <= self.threshold)
            last = first + (gaps[0] if len(gaps) else len(counts) - first) - 1
            width = (self.max - self.min) / self.size
            self.OBJECT[...] = (self.min + first * width, self.min + (last + 1) * width,
                                counts[first:last + 1].sum())
