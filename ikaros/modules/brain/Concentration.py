"""Concentration: a hormone-like level that rises with input and decays to a floor
(Ikaros 3)."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Concentration(Module):
    """One level y that starts at the floor g = gamma·tick_duration and each tick becomes
    y + alpha·ΣINPUT − beta·tick_duration·(y − g), then at least g (in float32). This is
    what Ikaros 3 computes, although its class file calls alpha the "nominal level", beta
    the "input gain" and gamma the "decay rate": in the code alpha is the input gain, beta
    the decay rate and gamma the floor (both rates, per second). An unconnected INPUT sums
    to 0. New in Ikaros 3."""

    alpha = Parameter(0.1, "the gain of the summed input")
    beta = Parameter(0.0001, "the decay rate towards the floor, per second")
    gamma = Parameter(0.25, "the floor (nominal level), per second: times tick_duration")
    INPUT = Input("the input; all elements are summed", optional=True, flatten=True)
    OUTPUT = Output("the level", size="1")

    def init(self):
        self.OUTPUT[0] = self.gamma * self.clock.tick_duration

    def tick(self):
        dt = np.float32(self.clock.tick_duration)
        floor = np.float32(self.gamma) * dt
        total = np.sum(self.INPUT, dtype=np.float32) if self.INPUT is not None else 0
        y = self.OUTPUT[0]
        y = y + np.float32(self.alpha) * total - np.float32(self.beta) * dt * (y - floor)
        self.OUTPUT[0] = max(y, floor)
