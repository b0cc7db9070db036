"""Counter: counts how often the input exceeds a threshold."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Counter(Module):
    """Counts the ticks on which at least one element of INPUT is above ``threshold``:
    COUNT is the number of such ticks and PERCENT that number as a fraction (0 ... 1, not
    a percentage, as in Ikaros 2) of the ticks counted. Ikaros 2 implemented only this
    counting: its ``mode`` ``component`` and ``any`` both count ticks, and so they do here
    (the golden files show it). ``mode="elements"`` (this project's) counts every element
    on its own instead: COUNT is the number of (tick, element) pairs above the threshold
    and PERCENT its fraction of all pairs counted. The original's class file gives
    ``threshold`` the default 0.5, but with it unset Ikaros 2 counts a value of 0.24 and
    not one of -0.73 (golden files), as with a threshold between 0 and 0.24: the default
    here is 0. Whether Ikaros 2 uses a threshold that the file sets, the golden files do
    not settle; this project uses it, so ``threshold="0.5"`` gives what the class file
    describes. Only ticks that are multiples of
    ``count_interval`` are counted. Every ``reset_interval`` ticks (from tick
    ``reset_interval`` on) the counts start again from 0 before the tick is counted, and
    every ``print_interval`` ticks the count is printed (0 never prints; when the original
    prints is not given by the golden files)."""

    mode = Parameter("component", "component and any (Ikaros 2): count ticks on which any "
                     "element is above the threshold; elements (this project's): count "
                     "each element", options="component/any/elements")
    threshold = Parameter(0.0, "a value counts when it is above this (the default 0 is what "
                          "Ikaros 2 counts with; its class file says 0.5)")
    reset_interval = Parameter(1000000, "ticks between resets of the counts to 0", type="int")
    print_interval = Parameter(1000, "ticks between printouts of the count; 0 never prints",
                               type="int")
    count_interval = Parameter(1, "count only on ticks that are multiples of this", type="int")
    INPUT = Input("the values to count")
    COUNT = Output("the count since the last reset", size="1")
    PERCENT = Output("the count as a fraction (0 ... 1) of what was counted since the last "
                     "reset", size="1")

    def init(self):
        self._count = 0
        self._total = 0

    def tick(self):
        tick = self.clock.tick
        if self.reset_interval > 0 and tick > 0 and tick % self.reset_interval == 0:
            self._count = 0
            self._total = 0
        if tick % max(1, self.count_interval) == 0:
            if self.mode == "elements":
                self._count += int(np.count_nonzero(self.INPUT > self.threshold))
                self._total += self.INPUT.size
            else:
                self._count += int(np.any(self.INPUT > self.threshold))
                self._total += 1
        self.COUNT[0] = self._count
        self.PERCENT[0] = self._count / self._total if self._total else 0.0
        if self.print_interval > 0 and (tick + 1) % self.print_interval == 0:
            self.print(f"count {self._count} ({100 * self.PERCENT[0]:.2f}%) at tick {tick}")
