"""Noise: adds Gaussian noise to a signal."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Noise(Module):
    """Adds Gaussian noise to its input: OUTPUT = INPUT + N(mean, sigma), with a new,
    independent sample for every element on every tick. The same ``seed`` gives the same
    noise."""

    sigma = Parameter(1.0, "standard deviation of the noise", range=(0, None))
    mean = Parameter(0.0, "mean of the noise")
    seed = Parameter(None, "seed of the random generator; unset (or 0) gives different noise "
                     "on every run", type="int")
    INPUT = Input("the signal")
    OUTPUT = Output("the signal with noise added", size_set="INPUT")

    def init(self):
        self._rng = np.random.default_rng(self.seed or None)
        self._input = self.INPUT.reshape(self.OUTPUT.shape)

    def tick(self):
        self._rng.standard_normal(out=self.OUTPUT, dtype=np.float32)
        self.OUTPUT *= np.float32(self.sigma)
        self.OUTPUT += np.float32(self.mean)
        self.OUTPUT += self._input
