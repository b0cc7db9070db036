"""Statistics: descriptive statistics, box plots, a histogram and statistical tests of
every sample of each input element (Ikaros 3)."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from . import _tests_statistical as tests

NAN = math.nan
_ROWS = ("count", "mean", "median", "mode", "min", "max", "variance", "sd", "skewness",
         "kurtosis")


def _quantile(s: np.ndarray, q: float) -> float:
    pos = q * (len(s) - 1)
    lo, hi = math.floor(pos), math.ceil(pos)
    return s[lo] + (s[hi] - s[lo]) * (pos - lo)


def describe(x: np.ndarray, running_mean: float) -> dict:
    """The descriptive statistics of one channel's history (MODULES-V3 §7.2)."""
    n = len(x)
    d = dict.fromkeys(_ROWS + ("q1", "q3", "iqr", "low_fence", "low_whisker", "high_whisker",
                               "high_fence"), NAN)
    d["count"] = n
    if n == 0:
        return d
    s = np.sort(x)
    d["mean"] = running_mean
    d["q1"], d["median"], d["q3"] = (_quantile(s, q) for q in (0.25, 0.5, 0.75))
    d["iqr"] = d["q3"] - d["q1"]
    d["low_fence"], d["high_fence"] = d["q1"] - 1.5 * d["iqr"], d["q3"] + 1.5 * d["iqr"]
    within_low, within_high = s[s >= d["low_fence"]], s[s <= d["high_fence"]]
    d["low_whisker"] = within_low[0] if len(within_low) else NAN      # s is sorted
    d["high_whisker"] = within_high[-1] if len(within_high) else NAN
    values, counts = np.unique(s, return_counts=True)
    d["mode"] = values[np.argmax(counts)]           # the first (smallest) of the most frequent
    d["min"], d["max"] = s[0], s[-1]
    dev = x - running_mean
    m2, m3, m4 = (dev ** 2).sum(), (dev ** 3).sum(), (dev ** 4).sum()
    if n >= 2:
        d["variance"] = m2 / (n - 1)
        d["sd"] = math.sqrt(d["variance"])
    s2 = d["variance"]
    if n >= 3:
        d["skewness"] = 0.0 if s2 == 0 else n * m3 / ((n - 1) * (n - 2) * s2 ** 1.5)
    if n >= 4:
        d["kurtosis"] = 0.0 if s2 == 0 else \
            (n * (n + 1) / (n - 1) * m4 / s2 ** 2 - 3 * (n - 1) ** 2) / ((n - 2) * (n - 3))
    return d


class Statistics(Module):
    """Collects every finite sample of each element (channel) of INPUT since the start (on
    ticks where SAMPLE, when connected, is at least 1 there) and reports, every tick, over
    the whole history: descriptive statistics (OUTPUT's rows: count, mean, median, mode,
    min, max, variance, standard deviation, skewness, excess kurtosis; also one output
    each, with Q1, Q3 and the interquartile range), box plots (fences at 1.5 IQR, whiskers,
    and the outliers in history order), a histogram of ``bins`` bins over the range of all
    channels, a test of the differences between channels (``parametric``: one-way ANOVA;
    ``non_parametric``: Kruskal–Wallis), an Anderson–Darling normality test of each channel,
    and pairwise tests (Welch's t test or Mann–Whitney U) with p-values adjusted by
    ``p_adjustment`` (none, bonferroni, holm or bh). Quantiles interpolate linearly; the
    mode is the smallest of the most frequent values; skewness and kurtosis are the sample
    (Joanes–Gill) estimates. Values that need more samples than there are are NaN. The
    formulas are those of Ikaros 3 (MODULES-V3 §7); the special functions are this
    project's (continued fractions to 3e-14). Reset of the state does not clear the
    histories, as in Ikaros 3. New in Ikaros 3."""

    bins = Parameter(10, "the number of histogram bins (at least 1 is used)", type="int")
    max_outliers = Parameter(32, "the rows of BOX_PLOT_OUTLIERS", type="int", range=(0, None))
    group_test = Parameter("parametric", "ANOVA (parametric) or Kruskal–Wallis",
                           options="parametric/non_parametric")
    labels = Parameter("", "comma-separated labels of the channels (labels only)")
    normality_test = Parameter("anderson_darling", "the normality test",
                               options="anderson_darling")
    pairwise_test = Parameter("parametric", "Welch's t test (parametric) or Mann–Whitney U",
                              options="parametric/non_parametric")
    p_adjustment = Parameter("holm", "the correction of the pairwise p-values",
                             options="none/bonferroni/holm/bh")
    INPUT = Input("the values, one channel per element (1-D)")
    SAMPLE = Input("where at least 1, that channel is sampled this tick", optional=True)
    OUTPUT = Output("rows: count, mean, median, mode, min, max, variance, sd, skewness, "
                    "kurtosis", shape="10, INPUT.size")
    COUNT = Output("the number of samples", shape="INPUT.size")
    MEAN = Output("the mean", shape="INPUT.size")
    MEDIAN = Output("the median", shape="INPUT.size")
    MODE = Output("the most frequent value (the smallest of a tie)", shape="INPUT.size")
    MIN = Output("the smallest sample", shape="INPUT.size")
    MAX = Output("the largest sample", shape="INPUT.size")
    VARIANCE = Output("the sample variance", shape="INPUT.size")
    STANDARD_DEVIATION = Output("the sample standard deviation", shape="INPUT.size")
    SKEWNESS = Output("the sample skewness", shape="INPUT.size")
    KURTOSIS = Output("the sample excess kurtosis", shape="INPUT.size")
    Q1 = Output("the first quartile", shape="INPUT.size")
    Q3 = Output("the third quartile", shape="INPUT.size")
    INTERQUARTILE_RANGE = Output("Q3 - Q1", shape="INPUT.size")
    BOX_PLOT = Output("rows: lower fence, lower whisker, Q1, median, Q3, upper whisker, upper "
                      "fence", shape="7, INPUT.size")
    BOX_PLOT_OUTLIERS = Output("the samples outside the fences, in history order (NaN: none)",
                               shape="@max_outliers, INPUT.size")
    HISTOGRAM = Output("one row of bin counts per channel", shape="INPUT.size, @bins")
    HISTOGRAM_MIN = Output("the lower end of the histogram (all channels)", size="1")
    HISTOGRAM_MAX = Output("the upper end of the histogram (all channels)", size="1")
    GROUP_TEST = Output("rows: p, statistic, df1, df2, effect size, groups", shape="6, 1")
    NORMALITY_TEST = Output("rows: A*, p, mean, sd", shape="4, INPUT.size")
    PAIRWISE_TEST_P = Output("the p-value of each pair of channels",
                             shape="INPUT.size, INPUT.size")
    PAIRWISE_TEST_P_ADJUSTED = Output("the adjusted p-values",
                                      shape="INPUT.size, INPUT.size")

    def init(self):
        if self.INPUT.ndim > 1 and max(self.INPUT.shape) != self.INPUT.size:
            self.fatal_error(f"INPUT must be 1-D (one channel per element), not "
                             f"{self.INPUT.shape}")
        if self.SAMPLE is not None and self.SAMPLE.size != self.INPUT.size:
            self.fatal_error(f"SAMPLE has {self.SAMPLE.size} elements; INPUT has "
                             f"{self.INPUT.size}")
        n = self.INPUT.size
        self._history = [[] for _ in range(n)]
        self._means = [0.0] * n

    def _collect(self):
        x = self.INPUT.reshape(-1)
        take = np.isfinite(x)
        if self.SAMPLE is not None:
            take &= self.SAMPLE.reshape(-1) >= 1
        for i in np.flatnonzero(take):
            v = float(x[i])
            history = self._history[i]
            history.append(v)
            k, m = len(history), self._means[i]
            self._means[i] = m * (k - 1) / k + v / k if (m < 0) != (v < 0) else m + (v - m) / k

    def tick(self):
        self._collect()
        data = [np.array(h) for h in self._history]
        stats = [describe(x, m) for x, m in zip(data, self._means)]
        column = {key: np.array([s[key] for s in stats]) for key in stats[0]} if stats else {}
        for row, key in enumerate(_ROWS):
            self.OUTPUT[row] = column[key]
        for name, key in (("COUNT", "count"), ("MEAN", "mean"), ("MEDIAN", "median"),
                          ("MODE", "mode"), ("MIN", "min"), ("MAX", "max"),
                          ("VARIANCE", "variance"), ("STANDARD_DEVIATION", "sd"),
                          ("SKEWNESS", "skewness"), ("KURTOSIS", "kurtosis"), ("Q1", "q1"),
                          ("Q3", "q3"), ("INTERQUARTILE_RANGE", "iqr")):
            getattr(self, name)[...] = column[key]
        for row, key in enumerate(("low_fence", "low_whisker", "q1", "median", "q3",
                                   "high_whisker", "high_fence")):
            self.BOX_PLOT[row] = column[key]
        self._outliers(data, stats)
        self._histogram(data)
        self.GROUP_TEST[:, 0] = tests.group_test(data, self.group_test == "parametric")
        for i, x in enumerate(data):
            self.NORMALITY_TEST[:, i] = tests.anderson_darling(x)
        self._pairwise(data)

    def _outliers(self, data, stats):
        self.BOX_PLOT_OUTLIERS[...] = NAN
        for i, (x, s) in enumerate(zip(data, stats)):
            lo, hi = s["low_fence"], s["high_fence"]
            if math.isfinite(lo) and math.isfinite(hi):
                out = x[(x < lo) | (x > hi)][:self.max_outliers]
                self.BOX_PLOT_OUTLIERS[:len(out), i] = out

    def _histogram(self, data):
        self.HISTOGRAM[...] = 0
        samples = [x for x in data if len(x)]
        if not samples:
            self.HISTOGRAM_MIN[0] = self.HISTOGRAM_MAX[0] = NAN
            return
        lo = min(x.min() for x in samples)
        hi = max(x.max() for x in samples)
        self.HISTOGRAM_MIN[0], self.HISTOGRAM_MAX[0] = lo, hi
        bins = self.HISTOGRAM.shape[1]
        for i, x in enumerate(data):
            index = np.zeros(len(x), np.int64) if hi == lo else \
                np.clip(np.floor((x - lo) / (hi - lo) * bins), 0, bins - 1).astype(np.int64)
            self.HISTOGRAM[i] = np.bincount(index, minlength=bins)[:bins]

    def _pairwise(self, data):
        n = len(data)
        test = tests.welch if self.pairwise_test == "parametric" else tests.mann_whitney
        p = np.ones((n, n))
        for i in range(n):
            for j in range(i + 1, n):
                p[i, j] = p[j, i] = test(data[i], data[j])
        self.PAIRWISE_TEST_P[...] = p
        self.PAIRWISE_TEST_P_ADJUSTED[...] = p if self.p_adjustment == "none" else \
            tests.adjust(p, self.p_adjustment)
