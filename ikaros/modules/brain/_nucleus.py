"""Shared parts of the nucleus-like brain models (Nucleus, NeuralField, NucleusEnsemble)."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter

ATAN_1 = math.atan(1.0)


def pooled(x, scale):
    """The sum of an input's elements, or their mean with ``scale``; 0 for None."""
    if x is None or x.size == 0:
        return 0.0
    return float(x.mean()) if scale else float(x.sum())


def shunting_factor(psi, s):
    """1 / (1 + psi * s) with the shunting term clipped at 0 (so the factor is in (0, 1])."""
    return 1.0 / (1.0 + np.maximum(psi * s, 0.0))


def scaled_atan(x):
    """0 for x <= 0, atan(x) / atan(1) above: f(1) = 1 and f approaches 2 as x grows."""
    return np.arctan(np.maximum(x, 0.0)) / ATAN_1


class ScalarNucleus(Module):
    """Base of Nucleus and NeuralField: one leaky unit driven by pooled inputs."""

    alpha = Parameter(0.0, "offset of the output (bias level)")
    beta = Parameter(1.0, "gain of the output")
    phi = Parameter(1.0, "weight of the excitation")
    chi = Parameter(1.0, "weight of the inhibition")
    psi = Parameter(1.0, "weight of the shunting inhibition")
    scale = Parameter(True, "yes: each input is pooled as the mean of its elements; no: as "
                      "their sum")
    epsilon = Parameter(0.1, "rate (0..1) at which the state approaches its drive each tick",
                        range=(0, 1))
    EXCITATION = Input("excitatory input; all elements are pooled", optional=True,
                       flatten=True)
    INHIBITION = Input("subtractive inhibitory input; all elements are pooled", optional=True,
                       flatten=True)
    SHUNTING_INHIBITION = Input("shunting (divisive) inhibition of the excitation; all "
                                "elements are pooled", optional=True, flatten=True)
    OUTPUT = Output("the activity of the unit", size="1")

    def init(self):
        self._x = 0.0
        self.OUTPUT[...] = self.alpha

    def tick(self):
        s = shunting_factor(self.psi, pooled(self.SHUNTING_INHIBITION, self.scale))
        drive = (self.phi * s * pooled(self.EXCITATION, self.scale)
                 - self.chi * pooled(self.INHIBITION, self.scale))
        self._x += self.epsilon * (drive - self._x)
        self.OUTPUT[...] = self.alpha + self.beta * scaled_atan(self._x)
