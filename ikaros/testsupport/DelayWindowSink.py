"""DelayWindowSink: checks a delay window of a DelaySequenceSource."""
from ikaros.module import Input, Parameter

from ikaros.testsupport._internal import WindowCheck, first_tick, sequence


class DelayWindowSink(WindowCheck):
    """INPUT is a delay window of a DelaySequenceSource (one lane per delay in ``delays``):
    lane k must hold the source's value of tick t - delays[k] (0 before the first tick)."""

    delays = Parameter([1], "the delay of each lane, in order", type="array")
    offset = Parameter(0.0, "the source's offset")
    INPUT = Input("the delay window")

    def expected(self, t):
        return [sequence(t - int(d), self.offset, first_tick(self)) for d in self.delays]
