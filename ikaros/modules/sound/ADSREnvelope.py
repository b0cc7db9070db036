"""ADSREnvelope: an attack-decay-sustain-release envelope at audio rate."""
import numpy as np

from ikaros.module import Input, Parameter

from ._block import AudioBlock, per_sample

IDLE, ATTACK, DECAY, SUSTAIN, RELEASE = range(5)
_EPSILON = 1e-9         # a segment ends when its level is this close to its end


class ADSREnvelope(AudioBlock):
    """An envelope generator (Ikaros 3's class, written here from its interface and the
    classic linear ADSR; Ikaros 3's own segment shapes are not documented): OUTPUT holds
    one envelope value per sample, sample_rate × tick_duration per tick, to multiply a
    sound with. A note starts when GATE or TRIG rises (goes above 0 after being 0 or below;
    the values are taken per sample when the input has one per sample, else its first
    element for the whole block): the level rises by 1/(attack·sample_rate) per sample
    (from where it is) until it reaches 1, then falls by (1 − sustain)/(decay·sample_rate)
    per sample until it reaches ``sustain``, and stays there while GATE is above 0. When
    GATE falls, or when the decay ends with GATE not above 0 (a note started by TRIG
    alone, or with GATE unconnected), the release takes the level from where it is to 0 in
    ``release`` seconds. A segment of 0 seconds is done in one sample. Each sample's value
    is the level after that sample's step; the level starts at 0 and carries over between
    ticks."""

    attack = Parameter(0.01, "seconds from 0 to 1", range=(0, None))
    decay = Parameter(0.1, "seconds from 1 down to sustain", range=(0, None))
    sustain = Parameter(0.7, "the level held while GATE is above 0", range=(0, 1))
    release = Parameter(0.2, "seconds from the level when the note ends down to 0",
                        range=(0, None))
    GATE = Input("the note is held while this is above 0; a rise starts it", optional=True)
    TRIG = Input("a rise starts the note (again, from the present level)", optional=True)

    def init(self):
        super().init()
        self._level = 0.0
        self._stage = IDLE
        self._release_step = 0.0
        self._gate = self._trig = False

    def tick(self):
        n = self.OUTPUT.size
        gates = (per_sample(self.GATE, n, 0.0) > 0).tolist()
        trigs = (per_sample(self.TRIG, n, 0.0) > 0).tolist()
        out = self.OUTPUT
        for i in range(n):
            gate, trig = gates[i], trigs[i]
            if (gate and not self._gate) or (trig and not self._trig):
                self._stage = ATTACK
            elif self._gate and not gate and self._stage != IDLE:
                self._start_release()
            self._gate, self._trig = gate, trig
            out[i] = self._step(gate)

    def _step(self, gate: bool) -> float:
        """Advance the level by one sample and return it."""
        stage, sr = self._stage, self.rate
        if stage == ATTACK:
            self._level += 1.0 / (self.attack * sr) if self.attack > 0 else 1.0
            if self._level >= 1.0 - _EPSILON:
                self._level, self._stage = 1.0, DECAY
        elif stage == DECAY:
            sustain = self.sustain
            self._level -= (1.0 - sustain) / (self.decay * sr) if self.decay > 0 else 1.0
            if self._level <= sustain + _EPSILON:
                self._level = sustain
                if gate:
                    self._stage = SUSTAIN
                else:
                    self._start_release()
        elif stage == SUSTAIN:
            self._level = self.sustain
        elif stage == RELEASE:
            self._level -= self._release_step
            if self._level <= _EPSILON:
                self._level, self._stage = 0.0, IDLE
        return self._level

    def _start_release(self):
        self._stage = RELEASE
        self._release_step = self._level / (self.release * self.rate) \
            if self.release > 0 else np.inf
