"""Noise: adds Gaussian or uniform noise to a signal."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._seeded import generator


class Noise(Module):
    """Adds noise to its input, a new, independent sample for every element on every tick.
    ``type`` gaussian: OUTPUT = INPUT + N(mean, standard deviation); uniform (Ikaros 3):
    OUTPUT = INPUT + U(min, max), uniform between the two bounds whichever is the larger
    (min above max is allowed, as in Ikaros 3). ``type`` may be given by its name or its
    index (0 gaussian, 1 uniform).

    In an Ikaros 2 file the defaults are Ikaros 2's (gaussian, ``sigma`` 1, ``mean`` 0) and
    the standard deviation is ``sigma``, or ``stddev`` when the module sets it. In an
    Ikaros 3 file they are Ikaros 3's (today's interface): uniform between ``min`` -0.1 and
    ``max`` 0.1, and a gaussian's standard deviation is ``stddev`` (0.1).

    The random numbers are NumPy's: the original draws from the C library's generator
    with a method no reference gives, so the same distribution comes out here, not the
    same numbers; no golden file holds Noise, whose values differ from run to run in the
    original too. A ``seed`` above 0 gives the same noise on every run; unset, 0 or
    negative (Ikaros 3's default -1) a different one. The bounds, mean and deviations
    must be finite numbers (NaN or inf is an error at load), and the deviations not
    negative; they may be changed while running, when a bad new value is refused with an
    error and the last valid one stays in use (Ikaros 3 takes the bad value and warns once
    that it keeps the last valid ones)."""

    type = Parameter("gaussian", "the kind of noise", options="gaussian,uniform",
                     default_v3="uniform")
    sigma = Parameter(1.0, "gaussian, Ikaros 2: standard deviation of the noise",
                      range=(0, None))
    stddev = Parameter(None, "gaussian, Ikaros 3: standard deviation of the noise (an "
                       "Ikaros 2 file: instead of sigma when set)", type="number",
                       range=(0, None), default_v3=0.1)
    mean = Parameter(0.0, "gaussian: mean of the noise")
    min = Parameter(-1.0, "uniform: one bound of the noise", default_v3=-0.1)
    max = Parameter(1.0, "uniform: the other bound of the noise", default_v3=0.1)
    seed = Parameter(None, "seed of the random generator; unset, 0 or negative: different "
                     "noise on every run", type="int", default_v3=-1)
    INPUT = Input("the signal")
    OUTPUT = Output("the signal with noise added", size_set="INPUT")

    def init(self):
        self._rng = generator(self.seed)
        self._input = self.INPUT.reshape(self.OUTPUT.shape)
        self._stddev = self.dialect == "3" or "stddev" in getattr(self.element, "attrs", {})

    def tick(self):
        if self.type == "uniform":
            low, high = sorted((float(self.min), float(self.max)))
            self._rng.random(out=self.OUTPUT, dtype=np.float32)
            self.OUTPUT[...] = low + self.OUTPUT.astype(np.float64) * (high - low)
        else:
            self._rng.standard_normal(out=self.OUTPUT, dtype=np.float32)
            self.OUTPUT *= np.float32(self.stddev if self._stddev else self.sigma)
            self.OUTPUT += np.float32(self.mean)
        self.OUTPUT += self._input
