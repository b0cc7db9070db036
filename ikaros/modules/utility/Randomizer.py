"""Randomizer: uniform random values."""
import numpy as np

from ikaros.module import Module, Output, Parameter


class Randomizer(Module):
    """Outputs uniform random values in [min, max). New values are drawn in init and on every
    tick that is a multiple of ``interval`` (tick 0, interval, 2*interval, ...); in between the
    output keeps its values. The size comes from ``outputsize`` or ``outputsize_x`` and
    ``outputsize_y``. The same ``seed`` gives the same values. ``min`` and ``max`` must be
    finite (an infinite or NaN bound is an error, as in Ikaros 3); min above max is allowed
    and gives values in (max, min]."""

    outputsize = Parameter(1, "number of elements of a 1-D output", type="int")
    outputsize_x = Parameter(None, "columns of a 2-D output", type="int")
    outputsize_y = Parameter(None, "rows of a 2-D output", type="int")
    min = Parameter(0.0, "the smallest value")
    max = Parameter(1.0, "the upper bound of the values")
    interval = Parameter(1, "ticks between new values", type="int", range=(1, None))
    seed = Parameter(None, "seed of the random generator; unset (or 0) gives a different run "
                     "every time", type="int")
    OUTPUT = Output("the random values",
                    size_param_x="outputsize_x", size_param_y="outputsize_y",
                    size_param="outputsize")

    def init(self):
        # An unset seed reads as 0, so 0 also means "a different run every time".
        self._rng = np.random.default_rng(self.seed or None)
        self._draw()

    def _draw(self):
        # in float64, so a range wider than float32 holds (-3e38 to 3e38) gives no overflow
        self._rng.random(out=self.OUTPUT, dtype=np.float32)
        self.OUTPUT[...] = self.min + self.OUTPUT.astype(np.float64) * (self.max - self.min)

    def tick(self):
        if self.clock.tick % max(1, self.interval) == 0:
            self._draw()
