"""AudioFilter: a resonant low-pass filter for audio, its cutoff moved by an envelope."""
import math

import numpy as np

from ikaros.module import Input, Parameter

from ._block import AudioBlock, per_sample

Q_MIN, Q_MAX = 1 / math.sqrt(2), 10.0       # the filter's Q at resonance 0 and 1


class AudioFilter(AudioBlock):
    """A low-pass filter for audio (Ikaros 3's class, written here from its interface: the
    filter is this project's reading, the second-order low-pass "biquad" of R. Bristow-
    Johnson's Audio EQ Cookbook). INPUT is one block of samples per tick (the first
    sample_rate × tick_duration of its elements are used; missing ones are 0). For each
    sample the cutoff is base·2^(envelope_amount·CUTOFF_MOD) Hz, where base is CUTOFF (when
    connected) or ``cutoff``: envelope_amount is the number of octaves the cutoff moves up
    when CUTOFF_MOD is 1 (an ADSREnvelope's output, for the classic synthesizer sweep);
    the cutoff is kept between 1 Hz and 0.49·sample_rate. ``resonance`` (plus
    RESONANCE_MOD, clipped to 0..1) sets the peak at the cutoff: the filter's Q goes from
    1/√2 (no peak, a Butterworth filter) at 0 to 10 at 1, Q = 1/√2 + resonance·(10 − 1/√2).
    With w = 2π·cutoff/sample_rate and α = sin(w)/(2Q) the filter is
    y[n] = (b0·x[n] + b1·x[n−1] + b2·x[n−2] − a1·y[n−1] − a2·y[n−2]) / a0 with
    b0 = b2 = (1 − cos w)/2, b1 = 1 − cos w, a0 = 1 + α, a1 = −2 cos w, a2 = 1 − α,
    its coefficients computed for every sample; the filter's memory carries over between
    ticks. CUTOFF, CUTOFF_MOD and RESONANCE_MOD give one value per sample when they are
    one-dimensional with a value per sample, else their first element for the block."""

    cutoff = Parameter(200.0, "the cutoff frequency in Hz (when CUTOFF is not connected)")
    resonance = Parameter(0.0, "0: no peak at the cutoff; 1: the highest (Q 10)",
                          range=(0, 1))
    envelope_amount = Parameter(4.0, "octaves the cutoff moves up per unit of CUTOFF_MOD")
    INPUT = Input("the sound to filter, one block of samples")
    CUTOFF = Input("the cutoff frequency in Hz, instead of the parameter cutoff",
                   optional=True)
    CUTOFF_MOD = Input("moves the cutoff by envelope_amount octaves per unit",
                       optional=True)
    RESONANCE_MOD = Input("added to resonance", optional=True)

    def init(self):
        super().init()
        self._memory = [0.0, 0.0, 0.0, 0.0]          # x[n-1], x[n-2], y[n-1], y[n-2]

    def tick(self):
        n, sr = self.OUTPUT.size, self.rate
        x = np.zeros(n, np.float64)
        source = self.INPUT.reshape(-1)[:n]
        x[:len(source)] = source
        base = per_sample(self.CUTOFF, n, self.cutoff)
        f = base * np.exp2(self.envelope_amount * per_sample(self.CUTOFF_MOD, n, 0.0))
        f = np.clip(np.nan_to_num(f, nan=1.0), 1.0, 0.49 * sr)
        r = np.clip(self.resonance + per_sample(self.RESONANCE_MOD, n, 0.0), 0.0, 1.0)
        b, a = lowpass_coefficients(f, r, sr)
        self.OUTPUT[:] = self._filter(x, b, a)

    def _filter(self, x: np.ndarray, b: np.ndarray, a: np.ndarray) -> list:
        x1, x2, y1, y2 = self._memory
        y = []
        for xn, b0, b1, b2, a1, a2 in zip(x.tolist(), *b.tolist(), *a.tolist()):
            yn = b0 * xn + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2
            x2, x1, y2, y1 = x1, xn, y1, yn
            y.append(yn)
        self._memory = [x1, x2, y1, y2]
        return y


def lowpass_coefficients(f: np.ndarray, resonance: np.ndarray, sr: float):
    """The cookbook low-pass filter's (b0, b1, b2) and (a1, a2), divided by a0, for each
    cutoff ``f`` (Hz) and resonance (0..1)."""
    q = Q_MIN + resonance * (Q_MAX - Q_MIN)
    w = 2 * np.pi * f / sr
    cos_w, alpha = np.cos(w), np.sin(w) / (2 * q)
    a0 = 1 + alpha
    b1 = (1 - cos_w) / a0
    b = np.stack([b1 / 2, b1, b1 / 2])
    a = np.stack([-2 * cos_w / a0, (1 - alpha) / a0])
    return b, a
