"""Shared parts of the nucleus-like brain models (Nucleus, NeuralField, NeuralArray,
NucleusEnsemble)."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter

ATAN_1 = math.atan(1.0)
TAN_1 = math.tan(1.0)


def pooled(x, scale):
    """The sum of an input's elements, or their mean with ``scale``; 0 for None."""
    if x is None or x.size == 0:
        return 0.0
    return float(x.mean()) if scale else float(x.sum())


def shunting_factor(psi, s):
    """1 / (1 + psi * s) with the shunting term clipped at 0 (so the factor is in (0, 1])."""
    return 1.0 / (1.0 + np.maximum(psi * s, 0.0))


def ikaros2_activation(x):
    """Ikaros 2's nucleus activation: atan(x) / tan(1) for x > 0 (the golden files show the
    divisor tan(1), not atan(1): f(1) = 0.504 and f tends to 1.009), 0 otherwise."""
    return math.atan(x) / TAN_1 if x > 0 else 0.0


class ScalarNucleus(Module):
    """Base of Nucleus and NeuralField: one leaky unit driven by pooled inputs, as Ikaros 2
    computes it."""

    alpha = Parameter(0.0, "offset of the output while the state is above 0")
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
        self.OUTPUT[...] = 0.0

    def tick(self):
        s = shunting_factor(self.psi, pooled(self.SHUNTING_INHIBITION, self.scale))
        drive = (self.phi * s * pooled(self.EXCITATION, self.scale)
                 - self.chi * pooled(self.INHIBITION, self.scale))
        self._x += self.epsilon * (drive - self._x)
        self.OUTPUT[0] = self.alpha + self.beta * ikaros2_activation(self._x) \
            if self._x > 0 else 0.0
