"""NeuralArray: an array of leaky units with excitation, inhibition and shunting."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._nucleus import pooled, shunting_factor


class NeuralArray(Module):
    """An array of leaky units, one per element of INHIBITION (which sets the size). Unit i
    has the drive a_i = phi * E_i / (1 + psi * S) - chi * I_i, where E is the element-wise
    EXCITATION (0 when unconnected), I the element-wise INHIBITION and S the shunting
    inhibition pooled over the whole SHUNTING_INHIBITION input (its mean with ``scale``, else
    its sum; a negative shunting term counts as 0). Each tick ACTIVITY += epsilon * (a -
    ACTIVITY) + alpha * (1 - ACTIVITY) + noise * N(0, 1), so alpha is a slow passive increase
    towards 1; ACTIVITY starts at 0. OUTPUT = beta * max(ACTIVITY, 0). The ``seed`` fixes the
    noise. This implements the equation of the class description (Ikaros 3 has no
    NeuralArray). It does not give Ikaros 2's values, a rule this project has not worked
    out. What the golden files of Ikaros 2 show, for an INHIBITION alone and the default
    parameters: OUTPUT stays 0; ACTIVITY is alpha plus a small random deviation (at most
    about 0.00023, exactly 0 on about a quarter of the elements) where an element is free,
    grows by about alpha a tick while it stays free, and is 0 otherwise; a negative
    INHIBITION element does not raise ACTIVITY (here it would); with a 3 x 4 INHIBITION that
    does not change, the free elements are a run of neighbours (wrapping from the last to
    the first) that moves from tick to tick. The deviations are the same on every run, but
    they are not any scaling of glibc's rand() / RAND_MAX values or of the usual Gaussian
    methods on them (Box-Muller, Marsaglia's polar method, the sum of 12), from any
    starting point in the first 300 000 draws."""

    alpha = Parameter(0.001, "passive increase of the activity towards 1, per tick")
    beta = Parameter(1.0, "gain of the output")
    phi = Parameter(1.0, "weight of the excitation")
    chi = Parameter(1.0, "weight of the inhibition")
    psi = Parameter(1.0, "weight of the shunting inhibition")
    scale = Parameter(True, "yes: the shunting input is pooled as the mean of its elements; "
                      "no: as their sum")
    epsilon = Parameter(0.1, "rate (0..1) at which the activity approaches its drive",
                        range=(0, 1))
    noise = Parameter(0.0, "standard deviation of Gaussian noise added to the activity each "
                      "tick")
    seed = Parameter(None, "seed of the noise; unset (or 0) gives a different run every time",
                     type="int")
    EXCITATION = Input("element-wise excitation; the size of INHIBITION", optional=True)
    INHIBITION = Input("element-wise inhibition; sets the size of the array")
    SHUNTING_INHIBITION = Input("shunting inhibition of the whole array; all elements are "
                                "pooled", optional=True, flatten=True)
    ACTIVITY = Output("the activity of the units", size_set="INHIBITION")
    OUTPUT = Output("the output of the units: beta * max(ACTIVITY, 0)", size_set="INHIBITION")

    def init(self):
        self._rng = np.random.default_rng(self.seed or None)
        if self.EXCITATION is not None and self.EXCITATION.size != self.ACTIVITY.size:
            self.fatal_error(f"EXCITATION has {self.EXCITATION.size} elements but INHIBITION "
                             f"has {self.ACTIVITY.size}; they must have the same size")
            self._e = None
        else:
            self._e = None if self.EXCITATION is None else self.EXCITATION.reshape(
                self.ACTIVITY.shape)
        self._a = np.zeros(self.ACTIVITY.shape)
        self.ACTIVITY[...] = 0
        self.OUTPUT[...] = 0

    def tick(self):
        a = self._a
        drive = -self.chi * self.INHIBITION.astype(np.float64)
        if self._e is not None:
            s = shunting_factor(self.psi, pooled(self.SHUNTING_INHIBITION, self.scale))
            drive += self.phi * s * self._e
        a += self.epsilon * (drive - a) + self.alpha * (1.0 - a)
        if self.noise:
            a += self._rng.normal(0.0, self.noise, a.shape)
        self.ACTIVITY[...] = a
        np.multiply(np.maximum(a, 0.0), self.beta, out=self.OUTPUT, casting="unsafe")
