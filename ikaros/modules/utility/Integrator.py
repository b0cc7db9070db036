"""Integrator: a leaky integrator or accumulator."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Integrator(Module):
    """Integrates INPUT over time: OUTPUT <- alpha * OUTPUT + beta * INPUT on every tick,
    starting from 0. With alpha = 1 it accumulates; with alpha < 1 it leaks (the defaults,
    alpha = 0.9 and beta = 0.1, make a low-pass filter with gain 1). When ``min`` or ``max`` is
    given the output is clipped to it after each update; left empty, that side is
    unlimited."""

    alpha = Parameter(0.9, "how much of the output is kept from one tick to the next")
    beta = Parameter(0.1, "how much of the input is added on each tick")
    min = Parameter("", "the lowest value of the output; empty: no limit", type="string")
    max = Parameter("", "the highest value of the output; empty: no limit", type="string")
    INPUT = Input("the signal to integrate")
    OUTPUT = Output("the integrated signal", size_set="INPUT")

    compiled_op = "integrator"   # an instruction of the compiled tick (ikaros/kernel/compiled/)

    @staticmethod
    def _limit(value, name):
        if value is None or (isinstance(value, str) and not value.strip()):
            return None
        try:
            return float(value)
        except (TypeError, ValueError):
            raise ValueError(f'{name} must be a number or empty, not "{value}"') from None

    def init(self):
        self._limit(self.min, "min")
        self._limit(self.max, "max")
        self.OUTPUT.fill(0)

    def tick(self):
        self.OUTPUT *= self.alpha
        self.OUTPUT += self.beta * self.INPUT
        low, high = self._limit(self.min, "min"), self._limit(self.max, "max")
        if low is not None or high is not None:
            np.clip(self.OUTPUT, low, high, out=self.OUTPUT)
