"""AudioSynth: a bank of oscillator voices, each with its wave, frequency, amplitude and gate."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._block import block_length, warn_if_not_whole
from ._waves import SHAPES, phases, wave

BLOCK_SECONDS = 0.1         # Ikaros 3 declares the block as sample_rate × 0.1 samples


class AudioSynth(Module):
    """A synthesizer of several voices (Ikaros 3's class, written here from its interface;
    how it uses its inputs is this project's reading). FREQUENCY has one element per voice
    (Hz); WAVESHAPE, AMPLITUDE and TRIGGER give the voice's wave (0 sine, 1 square, 2 saw,
    3 triangle, 4 ramp, 5 pulse with duty cycle 0.5, as AudioOscillator; rounded and kept
    in 0..5), its amplitude, and its gate: element k for voice k, or element 0 for every
    voice when the input is shorter. A voice sounds while its TRIGGER is above 0, and a
    rise of TRIGGER starts its wave from phase 0. OUTPUT is the sum of the sounding voices,
    amplitude·w(φ) each, with each voice's phase advancing by frequency / sample_rate per
    sample and carried over between ticks. As Ikaros 3 declares, a block is sample_rate ×
    0.1 samples, whatever the tick duration, so the blocks follow each other in real time
    only when a tick is 0.1 s."""

    sample_rate = Parameter(22050.0, "samples per second", fixed=True)
    WAVESHAPE = Input("the wave of each voice: 0 sine, 1 square, 2 saw, 3 triangle, 4 ramp, "
                      "5 pulse")
    FREQUENCY = Input("the frequency of each voice in Hz (one element per voice)")
    AMPLITUDE = Input("the amplitude of each voice")
    TRIGGER = Input("each voice sounds while this is above 0; a rise restarts its wave")
    OUTPUT = Output("this tick's block of samples, sample_rate × 0.1 of them, the sum of the "
                    "voices")

    def configure(self):
        self.set_output_shape("OUTPUT", block_length(self.sample_rate, BLOCK_SECONDS))

    def init(self):
        warn_if_not_whole(self, self.sample_rate, BLOCK_SECONDS)
        voices = self.FREQUENCY.size
        self._phase = [0.0] * voices
        self._gate = [False] * voices
        self._phases = np.empty(self.OUTPUT.size, np.float64)

    def tick(self):
        n, sr = self.OUTPUT.size, float(self.sample_rate)
        out = np.zeros(n, np.float64)
        for k, frequency in enumerate(self.FREQUENCY.reshape(-1).tolist()):
            gate = _voice(self.TRIGGER, k) > 0
            if gate and not self._gate[k]:
                self._phase[k] = 0.0
            self._gate[k] = gate
            steps = np.full(n, max(0.0, frequency) / sr)
            self._phase[k] = phases(self._phase[k], steps, self._phases)
            if gate:
                shape = SHAPES[int(np.clip(round(_voice(self.WAVESHAPE, k)), 0, 5))]
                out += _voice(self.AMPLITUDE, k) * wave(shape, self._phases)
        self.OUTPUT[:] = out


def _voice(x: np.ndarray, k: int) -> float:
    """Element k of an input, or element 0 when it is shorter (0 when empty)."""
    flat = x.reshape(-1)
    if flat.size == 0:
        return 0.0
    return float(flat[k] if k < flat.size else flat[0])
