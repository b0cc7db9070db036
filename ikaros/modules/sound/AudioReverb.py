"""AudioReverb: a room's reverberation, Schroeder–Moorer style."""
import numpy as np

from ikaros.module import Input, Parameter

from ._block import AudioBlock

# The delays (samples at 44.1 kHz) of Jezar's public-domain Freeverb: eight parallel
# low-pass feedback comb filters and four all-pass filters in series.
COMB_DELAYS = (1116, 1188, 1277, 1356, 1422, 1491, 1557, 1617)
ALLPASS_DELAYS = (556, 441, 341, 225)
ALLPASS_GAIN = 0.5
MAX_DECAY = 0.99                # comb feedback is kept below 1, so the tail always dies out


def scaled(delays, sample_rate: float) -> list[int]:
    """Freeverb's delays (for 44.1 kHz) at another sample rate, at least one sample each."""
    return [max(1, round(d * sample_rate / 44100)) for d in delays]


class AudioReverb(AudioBlock):
    """Reverberation (Ikaros 3's class, written here from its interface: the structure is
    this project's reading, a Schroeder–Moorer reverberator with the delays of Freeverb,
    scaled to the sample rate). INPUT is one block of samples per tick (the first
    sample_rate × tick_duration of its elements; missing ones are 0). The input goes
    through a pre-delay of round(pre_delay·sample_rate) samples, then into eight parallel
    comb filters with a low-pass filter in their feedback (comb delay M: out[n] =
    line[n−M]; s[n] = (1 − damping)·out[n] + damping·s[n−1]; line[n] = in[n] +
    decay·s[n], decay kept at 0.99 or below); the mean of the eight goes through four
    all-pass filters in series (Schroeder's, delay M: w[n] = in[n] + 0.5·w[n−M]; out[n] =
    w[n−M] − 0.5·w[n]). OUTPUT is (1 − mix)·INPUT + mix·(that wet sound). ``decay`` sets how
    long the reverberation lasts, ``damping`` how quickly its high frequencies die. All
    lines start silent and carry over between ticks; a change of pre_delay while the model
    runs starts a silent pre-delay line."""

    mix = Parameter(0.25, "0: the input only; 1: the reverberation only", range=(0, 1))
    decay = Parameter(0.7, "the feedback of the comb filters, 0..0.99: how long the "
                      "reverberation lasts", range=(0, 1))
    damping = Parameter(0.4, "0: the high frequencies last as long as the low; towards 1 "
                        "they die sooner", range=(0, 1))
    pre_delay = Parameter(0.03, "seconds before the reverberation starts", range=(0, None))
    INPUT = Input("the sound, one block of samples")

    def init(self):
        super().init()
        sr = self.rate
        self._combs = [[np.zeros(m), 0, 0.0] for m in scaled(COMB_DELAYS, sr)]
        self._allpasses = [[np.zeros(m), 0] for m in scaled(ALLPASS_DELAYS, sr)]
        self._pre = np.zeros(0)

    def tick(self):
        n = self.OUTPUT.size
        x = np.zeros(n)
        source = self.INPUT.reshape(-1)[:n]
        x[:len(source)] = source
        delayed = self._pre_delay(x)
        wet = self._allpass(np.mean([self._comb(c, delayed) for c in self._combs], axis=0))
        self.OUTPUT[:] = (1 - self.mix) * x + self.mix * wet

    def _pre_delay(self, x: np.ndarray) -> np.ndarray:
        """x delayed by the pre-delay; the line keeps the last samples for the next tick."""
        d = round(self.pre_delay * self.rate)
        if d == 0:
            return x
        if len(self._pre) != d:
            self._pre = np.zeros(d)
        joined = np.concatenate([self._pre, x])
        self._pre = joined[len(x):]
        return joined[:len(x)]

    def _comb(self, comb: list, x: np.ndarray) -> list:
        line, at, s = comb
        m = len(line)
        g, damp = min(self.decay, MAX_DECAY), self.damping
        out = []
        for xn in x.tolist():
            y = line[at]
            s = (1 - damp) * y + damp * s
            line[at] = xn + g * s
            at = at + 1 if at + 1 < m else 0
            out.append(y)
        comb[1], comb[2] = at, s
        return out

    def _allpass(self, x: np.ndarray) -> np.ndarray:
        for stage in self._allpasses:
            line, at = stage
            m = len(line)
            out = np.empty(len(x))
            for i, xn in enumerate(x.tolist()):
                v = line[at]
                w = xn + ALLPASS_GAIN * v
                out[i] = v - ALLPASS_GAIN * w
                line[at] = w
                at = at + 1 if at + 1 < m else 0
            stage[1] = at
            x = out
        return x
