"""The Ikaros 3 Nucleus as this project reads its interface: activation functions and the
burst cycle."""
import math

from ._nucleus import ikaros2_activation

ACTIVATIONS = {
    "atan": ikaros2_activation,
    "threshold": lambda u: 1.0 if u > 0 else 0.0,
    "ReLU": lambda u: max(u, 0.0),
    "tanh": math.tanh,
    "sigmoid": lambda u: 1.0 / (1.0 + math.exp(-u)) if u > -700 else 0.0,
    "linear": lambda u: u,
}


class BurstCycle:
    """A unit that bursts: once the state has stayed above the threshold for ``wait``
    seconds it gives the burst level for ``duration`` seconds, then its state is set to the
    reset level and for ``refractory`` seconds no burst starts. Times count in ticks of
    ``dt`` seconds."""

    def __init__(self, duration, refractory, wait):
        self.duration, self.refractory, self.wait = duration, refractory, wait
        self.bursting = 0.0     # time left of the burst
        self.resting = 0.0      # time left of the refractory period
        self.above = 0.0        # how long the state has been above the threshold

    def step(self, above_threshold: bool, dt: float) -> str:
        """One tick: "burst" (give the burst level), "end" (the burst just ended: reset the
        state) or "free" (give the activation)."""
        if self.bursting > 0:
            self.bursting -= dt
            if self.bursting <= 1e-12:
                self.bursting = 0.0
                self.resting = self.refractory
                self.above = 0.0
                return "end"
            return "burst"
        if self.resting > 0:
            self.resting = max(self.resting - dt, 0.0)
            return "free"
        self.above = self.above + dt if above_threshold else 0.0
        if above_threshold and self.above > self.wait + 1e-12:
            self.bursting = self.duration
            return "burst"
        return "free"
