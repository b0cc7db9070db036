"""Idle: spends time, for testing load and timing (Ikaros 3)."""
import math
import time

from ikaros.module import Module, Parameter


class Idle(Module):
    """Sleeps ``init`` seconds when the network starts and ``duration`` seconds on every
    tick, to test load and timing. Both parameters must be set (they have no default in
    Ikaros 3, where a model without them fails to build). New in Ikaros 3."""

    duration = Parameter(math.nan, "seconds slept on every tick (required)", finite=False)
    init_ = Parameter(math.nan, "seconds slept when the network starts (required)",
                      finite=False, name="init")

    def configure(self):
        for name, value in (("init", self.init_), ("duration", self.duration)):
            if math.isnan(value):
                raise ValueError(f'parameter "{name}" has no default value: set it')
            if not 0 <= value < math.inf:
                raise ValueError(f'parameter "{name}" must be a number of seconds >= 0, '
                                 f'not {value}')

    def init(self):
        self.print(f"Idle: sleeps {self.init_} s at the start and {self.duration} s per tick")
        time.sleep(self.init_)

    def tick(self):
        time.sleep(self.duration)
