"""AudioDelay: an echo with feedback, each repeat darker than the one before."""
import math

import numpy as np

from ikaros.module import Input, Parameter

from ._block import AudioBlock


class AudioDelay(AudioBlock):
    """An echo (Ikaros 3's class, written here from its interface: the structure is this
    project's reading, a delay line with a low-pass filter in its feedback path, as in
    analogue and tape echoes). INPUT is one block of samples per tick (the first
    sample_rate × tick_duration of its elements; missing ones are 0). With d =
    round(delay_time·sample_rate) samples (at least 1), for each sample x[n]:
    the echo e[n] = e[n−1] + k·(line[n−d] − e[n−1]) is the delay line's sample from d
    samples ago through a one-pole low-pass filter, k = 1 − exp(−2π·lowpass_cutoff /
    sample_rate) (lowpass_cutoff 0 or below: no filter, k = 1); the line takes
    x[n] + feedback_gain·e[n]; and OUTPUT is (1 − mix)·x[n] + mix·e[n]. The line starts
    silent and carries over between ticks; a change of delay_time while the model runs
    starts a silent line of the new length."""

    delay_time = Parameter(0.25, "seconds between a sound and its echo", range=(0, None))
    feedback_gain = Parameter(0.35, "how much of each echo is fed back (the next echo's "
                              "level relative to this one's)")
    mix = Parameter(0.5, "0: the input only; 1: the echoes only", range=(0, 1))
    lowpass_cutoff = Parameter(4000.0, "the cutoff (Hz) of the low-pass filter on the echoes; "
                               "0: no filter")
    INPUT = Input("the sound, one block of samples")

    def init(self):
        super().init()
        self._line = np.zeros(0)
        self._echo = 0.0

    def tick(self):
        n, sr = self.OUTPUT.size, self.rate
        d = max(1, round(self.delay_time * sr))
        if len(self._line) != d:
            self._line, self._at = np.zeros(d), 0
        x = np.zeros(n)
        source = self.INPUT.reshape(-1)[:n]
        x[:len(source)] = source
        k = 1.0 - math.exp(-2 * math.pi * self.lowpass_cutoff / sr) \
            if self.lowpass_cutoff > 0 else 1.0
        line, at, echo = self._line, self._at, self._echo
        gain, mix = self.feedback_gain, self.mix
        out = self.OUTPUT
        for i, xn in enumerate(x.tolist()):
            echo += k * (line[at] - echo)       # line[at] was written d samples ago
            line[at] = xn + gain * echo
            at = at + 1 if at + 1 < d else 0
            out[i] = (1 - mix) * xn + mix * echo
        self._at, self._echo = at, echo
