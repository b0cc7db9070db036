"""LeakyIntegrator: one non-negative integrator of excitation minus inhibition (Ikaros 3)."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class LeakyIntegrator(Module):
    """Integrates, each tick, ``excitation_gain`` times the sum of EXCITATION minus
    ``inhibition_gain`` times the sum of INHIBITION into one value, then decays it
    (``none``: no decay; ``linear``: minus decay_rate·tick_duration; ``exponential``: times
    1 − decay_rate·tick_duration) and keeps it at 0 or above. The state starts at 0 and is
    not reset. The Ikaros 3 build the reference was taken from stops with "Uninitialized
    parameter" when decay_type is linear or exponential (its decay_rate is never bound);
    here those decays work as its documentation describes. New in Ikaros 3."""

    decay_type = Parameter("none", "how the value decays each tick",
                           options="none/linear/exponential")
    decay_rate = Parameter(0.0, "decay per second (linear: an amount; exponential: a "
                           "fraction); multiplied by tick_duration")
    excitation_gain = Parameter(1.0, "the weight of the summed excitation")
    inhibition_gain = Parameter(1.0, "the weight of the summed inhibition")
    EXCITATION = Input("excitation; all elements are summed", flatten=True)
    INHIBITION = Input("inhibition; all elements are summed", flatten=True)
    OUTPUT = Output("the integrated value, never below 0", size="1")

    def init(self):
        self._x = 0.0

    def tick(self):
        x = self._x + self.excitation_gain * float(np.sum(self.EXCITATION, dtype=np.float64)) \
            - self.inhibition_gain * float(np.sum(self.INHIBITION, dtype=np.float64))
        rate = self.decay_rate * self.clock.tick_duration
        if self.decay_type == "linear":
            x -= rate
        elif self.decay_type == "exponential":
            x *= 1.0 - rate
        self._x = max(x, 0.0)
        self.OUTPUT[0] = self._x
