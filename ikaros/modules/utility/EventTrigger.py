"""EventTrigger: random events of a given duration."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from .._crand import module_rand


class EventTrigger(Module):
    """Generates random events. After ``initial_delay`` ticks with all outputs 0, one of the
    ``size`` outputs, chosen at random, is set to 1 for a while; then all outputs are 0 for
    a pause, and a new event starts. As in Ikaros 2 (golden files) an event lasts
    ``duration`` + 1 ticks and a pause ``timeout`` + 1 ticks (so timeout 0 still pauses a
    tick: this project's reading, as the golden files have no such case);
    ``timing="exact"`` (this project's) makes them last exactly ``duration`` and
    ``timeout`` ticks (timeout 0: no pause). The output is rand() % size, with rand() the
    C library's generator (glibc's) as Ikaros 2 draws it, unseeded as there; one that
    equals the last event's is drawn again, so the same output never comes twice in a row
    (the golden files also fit a choice among the others; this is this project's
    reading). The modules of a network share that generator, as Ikaros 2's share one;
    ``seed`` gives the module one of its own, seeded as srand does (a negative seed gives a
    different run every time). ``duration`` and ``timeout`` may give one value per output (the event's
    own duration, and the pause after it); a shorter list is extended with its last
    value. A NEXT input with any element above 0 starts a new event at once."""

    size = Parameter(1, "the number of outputs (possible events)", type="int")
    initial_delay = Parameter(0, "ticks before the first event", type="int")
    duration = Parameter("100", "ticks each event lasts (Ikaros 2: one more); one value, or "
                         "one per output", type="array")
    timeout = Parameter("0", "ticks with all outputs 0 after each event (Ikaros 2: one "
                        "more); one value, or one per output", type="array")
    timing = Parameter("original", "original: events and pauses last one tick longer than "
                       "duration and timeout, as in Ikaros 2; exact: as long as they say",
                       options="original/exact")
    seed = Parameter(None, "seed of the C library generator (as srand); unset: Ikaros 2's "
                     "unseeded sequence; negative: a different run every time", type="int")
    NEXT = Input("starts a new event when any element is above 0", optional=True)
    OUTPUT = Output("1 for the current event, 0 elsewhere", size_param="size")

    def init(self):
        self._rand = module_rand(self)
        self._current = -1          # the output that is on, or -1
        self._last = -1             # the last output that was on
        self._left = max(0, self.initial_delay)   # ticks left of the current phase
        self.OUTPUT.fill(0)

    def _ticks(self, values, k):
        """The length of a phase for output k: its duration or timeout value (plus one
        with the original timing)."""
        values = np.asarray(values).reshape(-1)
        value = int(round(float(values[min(k, values.size - 1)]))) if values.size else 0
        return value + 1 if self.timing == "original" else value

    def _start_event(self):
        n = self.OUTPUT.size
        k = self._rand.rand() % n
        while n > 1 and k == self._last:
            k = self._rand.rand() % n
        self.OUTPUT.fill(0)
        self.OUTPUT[k] = 1
        self._current = self._last = k
        self._left = max(1, self._ticks(self.duration, k))

    def tick(self):
        if self.NEXT is not None and np.any(self.NEXT > 0):
            self._start_event()
        elif self._left <= 0:
            pause = self._ticks(self.timeout, self._current) if self._current >= 0 else 0
            if self._current >= 0 and pause > 0:
                self.OUTPUT.fill(0)
                self._current = -1
                self._left = pause
            else:
                self._start_event()
        self._left -= 1
