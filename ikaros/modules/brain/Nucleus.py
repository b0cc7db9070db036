"""Nucleus: a generic brain nucleus."""
import numpy as np

from ikaros.module import Output, Parameter

from ._nucleus import ScalarNucleus, pooled, shunting_factor
from ._nucleus3 import ACTIVATIONS, BurstCycle


class Nucleus(ScalarNucleus):
    """A generic brain nucleus: one unit with state X driven by the pooled EXCITATION,
    INHIBITION and SHUNTING_INHIBITION inputs (E, I, S: the mean of their elements with
    ``scale`` / ``scale_inputs``, else the sum; an unconnected input gives 0, a negative
    shunting term counts as 0). X starts at 0.

    **Ikaros 2 file**: the drive a = phi * E / (1 + psi * S) - chi * I; each tick X +=
    epsilon * (a - X), and OUTPUT = alpha + beta * atan(X) / tan(1) while X > 0, 0
    otherwise. The golden files of Ikaros 2 show the atan divided by tan(1) (f(1) = 0.504,
    f tends to 1.009), the mean and the sum, epsilon, and 0 (not alpha) while X ≤ 0 with
    every weight set; they cannot tell whether alpha is added while X > 0 (no case sets it
    with X above 0), nor whether the inhibition's mean is taken over its own size or the
    excitation's (their sizes are equal there): this project adds alpha, and divides by the
    inhibition's size. The Ikaros 3 parameters have no effect in an Ikaros 2 file.

    **Ikaros 3 file** (this project's reading of Ikaros 3's interface; no run of the
    original was compared): the drive a = alpha + beta * E / (1 + delta * psi * S) - gamma
    * I, plus Gaussian noise of standard deviation ``sigma`` (``seed`` ≥ 0 fixes it); X +=
    min(1, epsilon * dt / time_constant) * (a - X), dt the tick duration in seconds (X = a
    with the defaults). OUTPUT = output_offset + output_scale * f(X - theta), f the
    ``activation_function``: atan (as in Ikaros 2: atan(u) / tan(1) for u > 0, else 0),
    threshold (1 for u > 0), ReLU, tanh, sigmoid (1 / (1 + e^-u)) or linear. With
    ``burst_duration`` above 0 the unit bursts: on the first tick X - theta has been above 0
    for more than ``burst_time`` seconds (counting that tick: at once with 0), OUTPUT is output_offset + output_scale * burst_level for
    burst_duration seconds; then X is set to ``reset_level`` and no burst starts for
    ``refractory_period`` seconds."""

    epsilon = Parameter(0.1, "rate (0..1) at which the state approaches its drive each tick "
                        "(Ikaros 3: with time_constant)", range=(0, 1), default_v3=1.0)
    gamma = Parameter(1.0, "Ikaros 3: weight of the inhibition")
    delta = Parameter(1.0, "Ikaros 3: weight of the shunting inhibition (with psi)")
    sigma = Parameter(0.0, "Ikaros 3: standard deviation of noise added to the drive",
                      range=(0, None))
    seed = Parameter(-1, "Ikaros 3: seed of the noise; -1 gives a different run every time",
                     type="int")
    theta = Parameter(0.0, "Ikaros 3: threshold subtracted from X before the activation")
    time_constant = Parameter(1.0, "Ikaros 3: time constant of X in seconds",
                              range=(0, None))
    scale_inputs = Parameter(True, "Ikaros 3: yes: each input is pooled as the mean of its "
                             "elements; no: as their sum")
    output_offset = Parameter(0.0, "Ikaros 3: added to the output")
    output_scale = Parameter(1.0, "Ikaros 3: gain of the output")
    activation_function = Parameter("atan", "Ikaros 3: the activation f of OUTPUT",
                                    options="atan,threshold,ReLU,tanh,sigmoid,linear")
    burst_duration = Parameter(0.0, "Ikaros 3: length of a burst in seconds (0: no bursts)",
                               range=(0, None))
    refractory_period = Parameter(0.0, "Ikaros 3: seconds after a burst before the next "
                                  "one", range=(0, None))
    reset_level = Parameter(0.0, "Ikaros 3: X after a burst")
    burst_level = Parameter(1.0, "Ikaros 3: the activation during a burst")
    burst_time = Parameter(0.0, "Ikaros 3: seconds X must stay above theta before a burst",
                           range=(0, None))
    X = Output("the state of the unit", size="1")

    def init(self):
        super().init()
        self.X[0] = 0.0
        if self.dialect == "3":
            self._rng = np.random.default_rng(None if self.seed < 0 else self.seed)
            self._burst = BurstCycle(self.burst_duration, self.refractory_period,
                                     self.burst_time) if self.burst_duration > 0 else None

    def tick(self):
        if self.dialect != "3":
            super().tick()
            self.X[0] = self._x
            return
        scale = self.scale_inputs
        s = shunting_factor(self.delta * self.psi, pooled(self.SHUNTING_INHIBITION, scale))
        drive = (self.alpha + self.beta * s * pooled(self.EXCITATION, scale)
                 - self.gamma * pooled(self.INHIBITION, scale))
        if self.sigma > 0:
            drive += self.sigma * float(self._rng.standard_normal())
        dt = self.clock.tick_duration or 1.0
        rate = min(1.0, self.epsilon * dt / self.time_constant) if self.time_constant > 0 \
            else 1.0
        self._x += rate * (drive - self._x)
        u = self._x - self.theta
        phase = self._burst.step(u > 0, dt) if self._burst is not None else "free"
        if phase == "end":
            self._x = self.reset_level
            u = self._x - self.theta
        value = self.burst_level if phase == "burst" else \
            ACTIVATIONS[self.activation_function](u)
        self.OUTPUT[0] = self.output_offset + self.output_scale * value
        self.X[0] = self._x
