"""DelayFlatWindowSink: checks a flattened delay window of a DelayVectorSource."""
from ikaros.module import Input, Parameter

from ikaros.testsupport._internal import WindowCheck, first_tick, vector


class DelayFlatWindowSink(WindowCheck):
    """INPUT is a flattened delay window of a DelayVectorSource: element 2k + c must hold
    channel c of the source's value at delay ``delays[k]`` (delay-major order)."""

    delays = Parameter([1], "the delay of each lane, in order", type="array")
    INPUT = Input("the flattened delay window", flatten=True)

    def expected(self, t):
        first = first_tick(self)
        return [v for d in self.delays for v in vector(t - int(d), first)]
