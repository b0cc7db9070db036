"""AudioOscillator: a block of audio samples of a wave per tick."""
import numpy as np

from ikaros.module import Input, Parameter

from ._block import AudioBlock, per_sample
from ._waves import SHAPES, phases, wave


class AudioOscillator(AudioBlock):
    """An oscillator at audio rate (Ikaros 3's class): every tick OUTPUT holds the next
    sample_rate × tick_duration samples of a wave. For sample i the frequency is
    f = max(0, base·multiplier + detune + modulation_gain·MODULATION), where base is
    INPUT (element i when INPUT is one-dimensional with a value per sample, else its first
    element; ``frequency`` when INPUT is not connected) and MODULATION is taken the same way
    (0 when not connected). The sample is volume·w(φ) for the phase φ in [0, 1), which then
    advances by f / sample_rate and keeps its fraction; the phase starts at 0 and carries
    over from tick to tick, so blocks join without a seam. w is the ``wave_shape``: sine
    sin 2πφ; square +1 where sin 2πφ > 0, else -1; saw 2φ - 1; triangle 4|φ - 0.5| - 1;
    ramp 1 - 2φ; pulse +1 where φ < duty_cycle, else -1. As in Ikaros 3, sample_rate (0 by
    default, normally set on the top group) must be set: 0 does not build."""

    wave_shape = Parameter("sine", "the wave", options=SHAPES)
    frequency = Parameter(440.0, "the base frequency in Hz when INPUT is not connected")
    detune = Parameter(0.0, "Hz added to the frequency")
    multiplier = Parameter(1.0, "the base frequency is multiplied by this")
    volume = Parameter(1.0, "the amplitude of the wave")
    modulation_gain = Parameter(1.0, "MODULATION is multiplied by this (Hz per unit) and "
                                "added to the frequency")
    duty_cycle = Parameter(0.5, "pulse: the part of the cycle at +1 (clipped to 0..1)")
    INPUT = Input("the base frequency in Hz: one value per sample, or one for the block",
                  optional=True)
    MODULATION = Input("added to the frequency after multiplying by modulation_gain: one "
                       "value per sample, or one for the block", optional=True)

    def init(self):
        super().init()
        self._phase = 0.0
        self._phases = np.empty(self.OUTPUT.size, np.float64)

    def tick(self):
        n = self.OUTPUT.size
        base = per_sample(self.INPUT, n, self.frequency)
        modulation = self.modulation_gain * per_sample(self.MODULATION, n, 0.0)
        f = np.maximum(0.0, base * self.multiplier + self.detune + modulation)
        self._phase = phases(self._phase, f / self.rate, self._phases)
        self.OUTPUT[:] = self.volume * wave(self.wave_shape, self._phases, self.duty_cycle)
