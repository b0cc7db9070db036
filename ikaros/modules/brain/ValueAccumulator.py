"""ValueAccumulator: a race of evidence accumulators that makes choices."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

BINS = 40           # rows of RT-HISTOGRAM
BIN_WIDTH = 5       # ticks per histogram row


class ValueAccumulator(Module):
    """An accumulator race (from the 2020 decision model), as Ikaros 2 computes it (Ikaros 3
    has no such class). INDEX is a one-hot (or graded) attention vector over the options
    and sets their number and shape; the evidence E is the sum of the positive elements of
    INPUT. Each tick every option's state is updated together: s = (1 - lambda) s + alpha *
    INDEX * E - beta * (1 - INDEX) * E + gamma * s, then each option is inhibited by the
    others, s_i -= delta * sum of the other states, then Gaussian noise N(mean, sigma) is
    added (with ``seed``) and s is clipped to 0..1. When an option reaches 1 it is chosen
    (the first such option): OUTPUT and CHOICE are one-hot for it on that tick, CHOICE_IX is
    its (flat) index until the next choice, the reaction time rt (the ticks since the
    previous choice, not counting the choice ticks) adds a count to row rt/5 of
    RT-HISTOGRAM (rt < 200), in the option's column (as in Ikaros 2, the option's flat index
    counts from the start of that row, so with more options than INDEX has columns it lands
    in a later row), CHOICE-COUNT, CHOICE-PROBABILITY (counts / total) and RT-MEAN are
    updated, and all states restart at 0. Otherwise OUTPUT and CHOICE are 0. The command
    ``reset`` clears the states and statistics. The golden files of Ikaros 2 show the
    update with alpha and beta, the positive evidence, the clipping, the choice, rt, the
    histogram and the statistics; lambda, gamma, delta and the noise (all 0 by default) are
    this project's reading of the class description."""

    alpha = Parameter(0.2, "gain of the evidence for the attended option")
    beta = Parameter(0.2, "gain of the evidence against the unattended options")
    gamma = Parameter(0.0, "self-excitation (feedback) of each state")
    delta = Parameter(0.0, "inhibition of each state by the sum of the others")
    # 'lambda' is a Python keyword: the value is read with getattr(self, "lambda")
    lambda_ = Parameter(0.0, "leak: fraction of each state lost per tick", name="lambda",
                        range=(0, 1))
    mean = Parameter(0.0, "mean of the noise added each tick")
    sigma = Parameter(0.0, "standard deviation of the noise added each tick")
    seed = Parameter(None, "seed of the noise; unset (or 0) gives a different run every time",
                     type="int")
    INDEX = Input("attention over the options (usually one-hot); sets their number and "
                  "shape")
    INPUT = Input("the evidence; its positive elements are summed", flatten=True)
    STATE = Output("the accumulator states", size_set="INDEX")
    OUTPUT = Output("one-hot for the option chosen on this tick, else 0", size_set="INDEX")
    CHOICE = Output("one-hot for the option chosen on this tick, else 0", size_set="INDEX")
    RT_HISTOGRAM = Output("reaction-time histogram: row r counts choices made after 5r .. "
                          "5r+4 ticks, one column per option",
                          shape=f"{BINS}, INDEX.size_x", name="RT-HISTOGRAM")
    RT_MEAN = Output("mean reaction time of each option", size_set="INDEX", name="RT-MEAN")
    CHOICE_COUNT = Output("number of times each option was chosen", size_set="INDEX",
                          name="CHOICE-COUNT")
    CHOICE_PROBABILITY = Output("fraction of the choices that went to each option",
                                size_set="INDEX", name="CHOICE-PROBABILITY")
    CHOICE_IX = Output("the index of the last option chosen (0 before the first choice)",
                       size="1")

    def init(self):
        self._rng = np.random.default_rng(self.seed or None)
        self._reset()

    def _reset(self):
        self._state = np.zeros(self.STATE.size)
        self._rt_sum = np.zeros(self.STATE.size)
        self._rt = 0
        for out in (self.STATE, self.OUTPUT, self.CHOICE, self.RT_HISTOGRAM, self.RT_MEAN,
                    self.CHOICE_COUNT, self.CHOICE_PROBABILITY, self.CHOICE_IX):
            out[...] = 0

    def command(self, name, x=0, y=0, value=None):
        if name == "reset":
            self._reset()

    def tick(self):
        s = self._state
        index = self.INDEX.reshape(-1).astype(np.float64)
        e = float(np.maximum(self.INPUT, 0).sum())
        leak = getattr(self, "lambda")
        s[...] = ((1 - leak) * s + self.alpha * index * e
                  - self.beta * (1 - index) * e + self.gamma * s)
        if self.delta:
            s -= self.delta * (s.sum() - s)
        if self.sigma or self.mean:
            s += self._rng.normal(self.mean, self.sigma, s.shape)
        np.clip(s, 0.0, 1.0, out=s)
        output, choice = self.OUTPUT.reshape(-1), self.CHOICE.reshape(-1)
        output[...] = 0
        choice[...] = 0
        if s.size and s.max() >= 1.0:
            c = int(np.argmax(s))
            output[c] = 1
            choice[c] = 1
            self.CHOICE_IX[0] = c
            cell = self._rt // BIN_WIDTH * self.RT_HISTOGRAM.shape[1] + c
            if self._rt // BIN_WIDTH < BINS and cell < self.RT_HISTOGRAM.size:
                self.RT_HISTOGRAM.reshape(-1)[cell] += 1
            count = self.CHOICE_COUNT.reshape(-1)
            count[c] += 1
            self.CHOICE_PROBABILITY[...] = self.CHOICE_COUNT / self.CHOICE_COUNT.sum()
            self._rt_sum[c] += self._rt
            counts = count.astype(np.float64)
            self.RT_MEAN.reshape(-1)[...] = np.divide(self._rt_sum, counts,
                                                      out=np.zeros_like(counts),
                                                      where=counts > 0)
            s[...] = 0
            self._rt = 0
        else:
            self._rt += 1
        self.STATE.reshape(-1)[...] = s
