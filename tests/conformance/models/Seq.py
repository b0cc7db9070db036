"""Test-only source: writes `base` in init and base+1+n in tick n (like Sweep min=100 step=1)."""
from ikaros.module import Module, Output, Parameter


class Seq(Module):
    """A counting source for the conformance tests."""
    base = Parameter(100.0, "the value written in init")
    OUTPUT = Output("the count", size="1")

    def init(self):
        self.OUTPUT[...] = self.base

    def tick(self):
        self.OUTPUT[...] = self.base + 1 + self.clock.tick
