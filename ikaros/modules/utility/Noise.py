"""Noise: adds Gaussian or uniform noise to a signal."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Noise(Module):
    """Adds noise to its input, a new, independent sample for every element on every tick.
    ``type`` gaussian (the default, and Ikaros 2's only kind): OUTPUT = INPUT + N(mean,
    sigma); uniform (Ikaros 3): OUTPUT = INPUT + U(min, max), uniform between the two bounds
    whichever is the larger (min above max is allowed, as in Ikaros 3). ``type`` may be
    given by its name or its index (0 gaussian, 1 uniform). The same ``seed`` gives the
    same noise. The bounds, mean and sigma must be finite numbers (NaN or inf is an error
    at load), and sigma not negative; they may be changed while running, when a bad new
    value is refused with an error and the last valid one stays in use (Ikaros 3 takes the
    bad value and warns once that it keeps the last valid ones)."""

    type = Parameter("gaussian", "the kind of noise", options="gaussian,uniform")
    sigma = Parameter(1.0, "gaussian: standard deviation of the noise", range=(0, None))
    mean = Parameter(0.0, "gaussian: mean of the noise")
    min = Parameter(-1.0, "uniform: one bound of the noise")
    max = Parameter(1.0, "uniform: the other bound of the noise")
    seed = Parameter(None, "seed of the random generator; unset (or 0) gives different noise "
                     "on every run", type="int")
    INPUT = Input("the signal")
    OUTPUT = Output("the signal with noise added", size_set="INPUT")

    def init(self):
        self._rng = np.random.default_rng(self.seed or None)
        self._input = self.INPUT.reshape(self.OUTPUT.shape)

    def tick(self):
        if self.type == "uniform":
            low, high = sorted((float(self.min), float(self.max)))
            self._rng.random(out=self.OUTPUT, dtype=np.float32)
            self.OUTPUT[...] = low + self.OUTPUT.astype(np.float64) * (high - low)
        else:
            self._rng.standard_normal(out=self.OUTPUT, dtype=np.float32)
            self.OUTPUT *= np.float32(self.sigma)
            self.OUTPUT += np.float32(self.mean)
        self.OUTPUT += self._input
