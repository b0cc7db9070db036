"""Counter: counts how often the input exceeds a threshold."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Counter(Module):
    """Counts input values above ``threshold``. In mode ``any`` COUNT is the number of counted
    ticks on which at least one input element is above the threshold, and PERCENT is that
    number in percent of the counted ticks. In mode ``component`` every element is counted
    on its own: COUNT is the number of (tick, element) pairs above the threshold and PERCENT
    is that number in percent of all counted pairs. (Ikaros 2 implemented only ``any`` and
    behaved that way in both modes; both are implemented here.) Only ticks that are multiples
    of ``count_interval`` are counted. Every ``reset_interval`` ticks the counts start again
    from 0, and every ``print_interval`` ticks the count is printed (0 never prints)."""

    mode = Parameter("component", "count elements one by one (component) or ticks on which "
                     "any element is above the threshold (any)", options="component/any")
    threshold = Parameter(0.5, "a value counts when it is above this")
    reset_interval = Parameter(1000000, "ticks between resets of the counts to 0", type="int")
    print_interval = Parameter(1000, "ticks between printouts of the count; 0 never prints",
                               type="int")
    count_interval = Parameter(1, "count only on ticks that are multiples of this", type="int")
    INPUT = Input("the values to count")
    COUNT = Output("the count since the last reset", size="1")
    PERCENT = Output("the count in percent of what was counted since the last reset",
                     size="1")

    def init(self):
        self._count = 0
        self._total = 0

    def tick(self):
        tick = self.clock.tick
        if self.reset_interval > 0 and tick > 0 and tick % self.reset_interval == 0:
            self._count = 0
            self._total = 0
        if tick % max(1, self.count_interval) == 0:
            if self.mode == "any":
                self._count += int(np.any(self.INPUT > self.threshold))
                self._total += 1
            else:
                self._count += int(np.count_nonzero(self.INPUT > self.threshold))
                self._total += self.INPUT.size
        self.COUNT[0] = self._count
        self.PERCENT[0] = 100.0 * self._count / self._total if self._total else 0.0
        if self.print_interval > 0 and (tick + 1) % self.print_interval == 0:
            self.print(f"count {self._count} ({self.PERCENT[0]:.2f}%) at tick {tick}")
