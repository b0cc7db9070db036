"""FunctionGenerator: a periodic function of time."""
import math

from ikaros.module import Module, Output, Parameter


class FunctionGenerator(Module):
    """Outputs a function of the tick t (0 on the first tick): offset + amplitude * f(p) with p
    = frequency * (t + shift), where f is ``sin`` (sin p), ``triangle`` (rises from 0 to 1 and
    falls back to 0 over each period of 2 pi), ``ramp`` (rises from 0 towards 1 over each
    period, then drops to 0), ``square`` (1 for the first ``duty`` fraction of each period,
    otherwise 0) or ``ticksquare`` (1 on the first ``tickduty`` ticks of every ``basetime``
    ticks, otherwise 0; it ignores frequency and shift). The phase within a period is taken with
    trunc as Ikaros 2 and 3 do, so a negative t + shift mirrors the wave; ``fraction="floor"``
    (this project's) continues the same periodic wave instead. As in Ikaros 2 every element
    of the output gets the same value (``size`` is the number of elements). The output is 0 in init. ``type`` may be given by
    its label (``type="triangle"``, as Ikaros 3 files do) or by its index (``type="1"``, the
    Ikaros 2 list value). A ``basetime`` below 1 gives f = 0 and a warning. An inverted ramp
    comes from offset = 1 and amplitude = -1.

    In an Ikaros 3 file (dialect 3) the function is of the time in seconds (``tick *
    tick_duration``, tick counted as Ikaros 3 counts it) instead of the tick, ticksquare
    counts whole seconds (the time truncated to an integer), and the defaults are Ikaros 3's (frequency 440, basetime 100, tickduty 50). ``sine`` is Ikaros 3's label for
    ``sin``."""

    fraction = Parameter("trunc", "how the phase within a period is taken: trunc (the original; "
                      "a negative time mirrors the wave) or floor (the wave continues)",
                      options="trunc/floor")
    size = Parameter(1, "the number of elements of the output, each holding the same value",
                     type="int", range=(1, None))
    type = Parameter("sin", "the function", options="sin/triangle/ramp/square/ticksquare/sine")
    offset = Parameter(0.0, "a constant added to the output")
    amplitude = Parameter(1.0, "the factor f is multiplied by")
    frequency = Parameter(0.15707963267949, "radians per tick; the period is 2 pi / frequency "
                          "ticks (the default gives 40 ticks); Ikaros 3: radians per second",
                          default_v3=440.0)
    shift = Parameter(0.0, "a shift of the time, in ticks, added before multiplying by the "
                      "frequency")
    duty = Parameter(0.5, "the fraction of each period the square wave is 1", range=(0, 1))
    basetime = Parameter(2, "the period of ticksquare, in ticks (Ikaros 3: seconds)",
                         type="int", default_v3=100)
    tickduty = Parameter(1, "the number of ticks of each period ticksquare is 1 (Ikaros 3: "
                         "seconds)", type="int", default_v3=50)
    OUTPUT = Output("the value of the function, in every element", size_param="size")

    def init(self):
        self._warned = False
        self.OUTPUT.fill(0)

    def _value(self, t, fraction):
        kind = self.type
        if kind == "ticksquare":
            if self.basetime < 1:
                if not self._warned:
                    self._warned = True
                    self.warning(f"basetime must be at least 1, not {self.basetime}; "
                                 "ticksquare is 0")
                return 0.0
            return 1.0 if t % self.basetime < self.tickduty else 0.0
        p = self.frequency * (t + self.shift)
        if kind in ("sin", "sine"):
            return math.sin(p)
        phase = p / (2 * math.pi)
        phase -= fraction(phase)            # floor: 0 <= phase < 1
        if kind == "triangle":
            v = 2 * phase
            return v if v < 1 else 2 - v
        if kind == "ramp":
            return phase
        return 1.0 if phase < self.duty else 0.0      # square

    def tick(self):
        if self.dialect == "3":
            t = self.clock.time
            t = int(t) if self.type == "ticksquare" else t
        else:
            t = self.clock.tick
        value = self._value(t, math.floor if self.fraction == "floor" else math.trunc)
        value = self.offset + self.amplitude * value
        self.OUTPUT.fill(value)
