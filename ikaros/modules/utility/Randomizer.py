"""Randomizer: uniform random values."""
import numpy as np

from ikaros.module import Module, Output, Parameter

from ._seeded import generator


class Randomizer(Module):
    """Outputs uniform random values in [min, max). New values are drawn in init and on every
    tick that is a multiple of ``interval`` (tick 0, interval, 2*interval, ...); in between the
    output keeps its values. The size comes from ``outputsize`` or ``outputsize_x`` and
    ``outputsize_y`` (Ikaros 2) when they are set, and otherwise from ``size`` (Ikaros 3:
    a shape such as "2,3" for 2 rows of 3, the default in an Ikaros 3 file; 1 in an Ikaros
    2 file). A ``seed``
    above 0 gives the same values on every run; unset, 0 or negative (Ikaros 3's default
    -1) a different run every time. ``min`` and ``max`` must be finite (an infinite or NaN
    bound is an error, as in Ikaros 3); min above max is allowed and gives values in (max,
    min]. The random numbers are NumPy's: the original draws from the C library's
    generator in a way no reference gives, so the same distribution comes out, not the
    same numbers (no golden file holds Randomizer, whose values differ from run to run in
    the original too)."""

    size = Parameter("1", "Ikaros 3: the shape of the output, such as \"2,3\" (rows, "
                     "columns), when outputsize is not set", default_v3="2,3")
    outputsize = Parameter(None, "number of elements of a 1-D output", type="int")
    outputsize_x = Parameter(None, "columns of a 2-D output", type="int")
    outputsize_y = Parameter(None, "rows of a 2-D output", type="int")
    min = Parameter(0.0, "the smallest value")
    max = Parameter(1.0, "the upper bound of the values")
    interval = Parameter(1, "ticks between new values", type="int", range=(1, None))
    seed = Parameter(None, "seed of the random generator; unset, 0 or negative: a different "
                     "run every time", type="int", default_v3=-1)
    OUTPUT = Output("the random values",
                    size_param_x="outputsize_x", size_param_y="outputsize_y",
                    size_param="outputsize", size="@size")

    def init(self):
        self._rng = generator(self.seed)
        self._draw()

    def _draw(self):
        # in float64, so a range wider than float32 holds (-3e38 to 3e38) gives no overflow
        self._rng.random(out=self.OUTPUT, dtype=np.float32)
        self.OUTPUT[...] = self.min + self.OUTPUT.astype(np.float64) * (self.max - self.min)

    def tick(self):
        if self.clock.tick % max(1, self.interval) == 0:
            self._draw()
