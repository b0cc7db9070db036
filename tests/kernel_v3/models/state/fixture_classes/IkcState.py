"""IkcState: the implementation of fixture_classes/IkcState.ikc (test_153b)."""
from ikaros.module import Module


class IkcState(Module):
    def tick(self):
        self.SUM += self.INPUT
        self.ticks += 1
        self.OUTPUT[...] = self.SUM * self.scale
