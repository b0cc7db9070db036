"""DelayStackedWindowSink: checks stacked delay windows of several sequence sources."""
from ikaros.module import Input, Parameter

from ikaros.testsupport._internal import WindowCheck, first_tick, sequence


class DelayStackedWindowSink(WindowCheck):
    """INPUT stacks one delay window per connection (DelaySequenceSources with the given
    ``offsets``, in connection order): slice s, lane k must hold source s's value at delay
    ``delays[k]``."""

    delays = Parameter([1], "the delay of each lane, in order", type="array")
    offsets = Parameter([0], "the offset of each source, in connection order", type="array")
    INPUT = Input("the stacked delay windows", stack=True)

    def expected(self, t):
        first = first_tick(self)
        return [[sequence(t - int(d), o, first) for d in self.delays] for o in self.offsets]
