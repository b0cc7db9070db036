"""Histogram: counts input values into bins, over time."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Histogram(Module):
    """Counts the first element of INPUT into ``size`` equal bins over ``min`` .. ``max`` and
    adds the counts up over the ticks, never clearing them, as Ikaros 2 does (golden files):
    OUTPUT[k] is the number of values seen so far in bin k, which holds min + k * w <= x <
    min + (k + 1) * w with w = (max - min) / size. ``elements="all"`` (this project's)
    counts every element of INPUT instead. Values outside min .. max are ignored when
    ``ignore_outliers`` is set, and otherwise counted in the first or last bin; NaN values
    are never counted. When TRIG is connected, values are counted only on ticks where its
    first element is above 0. The golden files settle the bins inside min .. max; at the
    edges this is this project's reading: a value equal to max goes in the last bin, one
    just below min is an outlier. With max equal to min nothing is counted and a warning
    is given once. The command ``reset`` sets all counts to 0."""

    size = Parameter(15, "number of bins", type="int", range=(1, None))
    min = Parameter(0.0, "the lower end of the first bin")
    max = Parameter(1.0, "the upper end of the last bin")
    ignore_outliers = Parameter(True, "ignore values outside min .. max; otherwise count them "
                                "in the first or last bin")
    elements = Parameter("first", "which elements of INPUT are counted: first (Ikaros 2) or "
                         "all (this project's)", options="first/all")
    INPUT = Input("the values to count: its first element (or every element, with "
                  "elements=all)")
    TRIG = Input("when connected, values are counted only while its first element is above 0",
                 optional=True)
    OUTPUT = Output("the count of each bin", size_param="size")

    def init(self):
        self._warned = False
        self.OUTPUT.fill(0)

    def command(self, name, x=0, y=0, value=None):
        if name == "reset":
            self.OUTPUT.fill(0)

    def tick(self):
        if self.TRIG is not None and not self.TRIG.flat[0] > 0:
            return
        low, high, n = float(self.min), float(self.max), self.OUTPUT.size
        if high == low:
            if not self._warned:
                self._warned = True
                self.warning("max equals min: nothing is counted")
            return
        x = self.INPUT.reshape(-1).astype(np.float64)
        if self.elements == "first":
            x = x[:1]
        x = x[~np.isnan(x)]
        position = (x - low) / (high - low) * n
        index = np.floor(position)
        index[position == n] = n - 1                 # x == max goes in the last bin
        if self.ignore_outliers:
            index = index[(index >= 0) & (index < n)]
        else:
            index = np.clip(index, 0, n - 1)
        self.OUTPUT += np.bincount(index.astype(np.int64), minlength=n)[:n]
