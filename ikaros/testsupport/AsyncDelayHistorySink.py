"""AsyncDelayHistorySink: checks that the history of an asynchronous counter stays frozen
while its job runs."""
from ikaros.module import Input, Parameter

from ikaros.testsupport._internal import InternalModule


class AsyncDelayHistorySink(InternalModule):
    """INPUT is a delay window [1:n] of an asynchronous AsyncLifecycleTestModule's OUTPUT
    (the number of its finished ticks). The window must hold the last finished values, each
    once: lane k is lane 0 minus k (0 before the first values). At the end it prints
    ``ASYNC DELAY HISTORY TEST OK`` if that held on every tick, at least ``minimum`` jobs
    finished and a job ran over more than one tick; else ``ASYNC DELAY HISTORY TEST FAILED``
    with the reason."""

    minimum = Parameter(2, "the fewest finished jobs the run must see", type="int")
    INPUT = Input("the delay window")

    def init(self):
        self._wrong = None
        self._held = 0      # ticks on which the newest value was the one of the tick before
        self._last = 0.0

    def tick(self):
        lanes = [float(v) for v in self.INPUT.reshape(-1)]
        expected = [max(lanes[0] - k, 0.0) for k in range(len(lanes))]
        if lanes != expected and self._wrong is None:
            self._wrong = f"tick {self.clock.tick}: {lanes}"
        if lanes[0] == self._last and lanes[0] > 0:
            self._held += 1
        self._last = lanes[0]

    def stop(self):
        if self._wrong:
            why = f"the history moved: {self._wrong}"
        elif self._last < self.minimum:
            why = f"only {self._last:g} jobs finished"
        elif not self._held:
            why = "no job ran over more than one tick"
        else:
            self.print("ASYNC DELAY HISTORY TEST OK")
            return
        self.print(f"ASYNC DELAY HISTORY TEST FAILED: {why}")
