"""Oscillator: sine or square oscillations, one per frequency (Ikaros 3)."""
import numpy as np

from ikaros.module import Module, Output, Parameter


class Oscillator(Module):
    """Outputs sin(2π·f·t) for every frequency f of ``frequency`` (Hz), at the time t in
    seconds (rounded to float32 and computed in double, as Ikaros 3 does); ``square`` gives
    1 where that sine is > 0 and 0 elsewhere (not ±1). With an integer frequency and the
    time a whole number of seconds the sine is about 0 and the square wave follows its
    rounding noise, as in the original. The output has the shape of ``frequency`` and is 0
    before the first tick. New in Ikaros 3."""

    type = Parameter("sin", "the waveform", options="sin/square")
    frequency = Parameter("1", "one frequency in Hz per output element", type="matrix",
                          finite=False)
    OUTPUT = Output("the oscillations, shaped like frequency", shape="frequency.shape")

    def tick(self):
        t = float(np.float32(self.clock.time))
        wave = np.sin(2.0 * np.pi * t * self.frequency.astype(np.float64))
        if self.type == "square":
            wave = wave > 0
        self.OUTPUT[...] = wave
