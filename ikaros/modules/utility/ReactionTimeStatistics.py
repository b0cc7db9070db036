"""ReactionTimeStatistics: reaction-time histograms and choice statistics."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class ReactionTimeStatistics(Module):
    """Collects reaction-time statistics for several response channels. A trial starts on a
    tick when any element of START is above 0: the reaction-time counter is set to 0, and it
    grows by 1 at the end of every tick, so it counts ticks. On a tick when any element of
    STOP is above 0, a response is recorded for the channel with the largest STOP value (the
    first one on ties), with the current count as its reaction time (REACTIONTIME): it is
    added to bin floor(rt * bins / max_rt) of that channel's column of RT-HISTOGRAM, or to
    RT-OUTLIER when it falls outside the bins; CHOICE-COUNT, CHOICE-PROBABILITY (the counts
    divided by their total) and RT-MEAN (the mean reaction time per channel, 0 before its
    first response) are updated. STOP is checked before START, so the same signal can go to
    both to time the intervals between events; the counter keeps running after a response,
    so several responses per trial are possible. STARTBALANCE is the number of starts minus
    the number of responses. Reaction times and ``max_rt`` are in ticks. The command
    ``reset`` clears the statistics.

    As Ikaros 2 computes it (golden files), the default: the reaction time of a response
    before the first start counts from tick 0; an outlier is counted in CHOICE-COUNT a
    second time instead of in RT-OUTLIER (which stays 0), so RT-MEAN, the sum of the
    reaction times divided by CHOICE-COUNT, and CHOICE-PROBABILITY count it twice; and
    RT-HISTOGRAM has one column per column of STOP (a matrix STOP's channels are its
    elements in row-major order, and channel c's bin b is the element at b * columns + c
    of the histogram, read row by row, left out past its end). ``counting="corrected"``
    (this project's) ignores responses before the first start, counts outliers once, in
    RT-OUTLIER, and gives RT-HISTOGRAM one column per channel."""

    bins = Parameter(40, "number of bins of the reaction-time histogram", type="int",
                     range=(1, None))
    max_rt = Parameter(1.0, "the reaction time, in ticks, at the upper end of the last bin")
    counting = Parameter("original", "original: as Ikaros 2 (outliers counted twice in "
                         "CHOICE-COUNT, times from tick 0 before the first start); corrected: "
                         "outliers in RT-OUTLIER, responses before the first start ignored",
                         options="original/corrected", fixed=True)
    START = Input("a trial starts when any element is above 0")
    STOP = Input("one element per response channel; a response is recorded for the channel "
                 "that is above 0 (the largest one)")
    RT_HISTOGRAM = Output("reaction-time histogram: one row per bin, one column per channel "
                          "(original: per column of STOP)", name="RT-HISTOGRAM")
    RT_OUTLIER = Output("per channel, the number of reaction times outside the histogram",
                        name="RT-OUTLIER", size_set="STOP")
    RT_MEAN = Output("per channel, the mean reaction time in ticks", name="RT-MEAN",
                     size_set="STOP")
    CHOICE_COUNT = Output("per channel, the number of responses", name="CHOICE-COUNT",
                          size_set="STOP")
    CHOICE_PROBABILITY = Output("per channel, the fraction of all responses",
                                name="CHOICE-PROBABILITY", size_set="STOP")
    STARTBALANCE = Output("starts minus responses", size="1")
    REACTIONTIME = Output("the reaction time of the latest response, in ticks", size="1")

    def set_sizes(self):
        shape = self.input_shape("STOP")
        if shape is None:
            return
        columns = shape[-1] if self.counting == "original" and shape else int(np.prod(shape))
        self.set_output_shape("RT-HISTOGRAM", (self.bins, columns))

    def init(self):
        self._original = self.counting == "original"
        self._histogram = self.RT_HISTOGRAM.reshape(-1)
        self._stop = self.STOP.reshape(-1)
        self._outlier = self.RT_OUTLIER.reshape(-1)
        self._mean = self.RT_MEAN.reshape(-1)
        self._count = self.CHOICE_COUNT.reshape(-1)
        self._prob = self.CHOICE_PROBABILITY.reshape(-1)
        self._sum = np.zeros(self._stop.size, dtype=np.float64)
        self._rt = 0
        self._started = self._original         # Ikaros 2 times from tick 0
        self._balance = 0
        self._warned = False
        self._clear()

    def _clear(self):
        for out in (self.RT_HISTOGRAM, self.RT_OUTLIER, self.RT_MEAN, self.CHOICE_COUNT,
                    self.CHOICE_PROBABILITY):
            out.fill(0)
        self._sum[:] = 0

    def tick(self):
        if self._started and self._stop.size and self._stop.max() > 0:
            c = int(np.argmax(self._stop))
            rt = self._rt
            self.REACTIONTIME[0] = rt
            bins = self.RT_HISTOGRAM.shape[0]
            if self.max_rt > 0:
                b = int(np.floor(rt * bins / self.max_rt))
            else:
                b = -1
                if not self._warned:
                    self._warned = True
                    self.warning("max_rt must be above 0; every reaction time is an outlier")
            if 0 <= b < bins:
                at = b * self.RT_HISTOGRAM.shape[1] + c
                if at < self._histogram.size:
                    self._histogram[at] += 1
            elif self._original:
                self._count[c] += 1                 # Ikaros 2 counts an outlier twice
            else:
                self._outlier[c] += 1
            self._count[c] += 1
            self._sum[c] += rt
            np.divide(self._count, self._count.sum(), out=self._prob)
            np.divide(self._sum, np.maximum(self._count, 1), out=self._mean,
                      casting="unsafe")
            self._balance -= 1
        if self.START.size and self.START.max() > 0:
            self._rt = 0
            self._started = True
            self._balance += 1
        self.STARTBALANCE[0] = self._balance
        self._rt += 1

    def command(self, name, x=0, y=0, value=None):
        if name == "reset":
            self._clear()
