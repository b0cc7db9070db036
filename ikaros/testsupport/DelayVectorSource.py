"""DelayVectorSource: outputs [tick, tick + 100]."""
from ikaros.module import Output

from ikaros.testsupport._internal import InternalModule, vector


class DelayVectorSource(InternalModule):
    """OUTPUT is [t, t + 100] on tick t (the first tick is 0, or 1 in an
    Ikaros 3 file); [0, 0] in init."""

    OUTPUT = Output("[tick, tick + 100]", shape="2")

    def tick(self):
        self.OUTPUT[:] = vector(self.clock.tick)
