"""DelaySequenceSource: outputs its tick plus an offset."""
from ikaros.module import Output, Parameter

from ikaros.testsupport._internal import InternalModule, sequence


class DelaySequenceSource(InternalModule):
    """OUTPUT (1 element) is tick + ``offset`` on every tick (the first tick is 0, or 1 in
    an Ikaros 3 file); 0 in init."""

    offset = Parameter(0.0, "added to the tick")
    OUTPUT = Output("tick + offset", shape="1")

    def tick(self):
        self.OUTPUT[0] = sequence(self.clock.tick, self.offset)
