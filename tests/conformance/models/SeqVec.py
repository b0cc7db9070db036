"""Test-only source with two elements: [s, s+100] where s is the Seq value."""
from ikaros.module import Module, Output


class SeqVec(Module):
    """Writes [100, 200] in init and [101+n, 201+n] in tick n."""
    OUTPUT = Output("the count and the count plus 100", size="2")

    def init(self):
        self.OUTPUT[:] = (100, 200)

    def tick(self):
        n = self.clock.tick
        self.OUTPUT[:] = (101 + n, 201 + n)
