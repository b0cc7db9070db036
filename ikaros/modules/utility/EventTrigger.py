"""EventTrigger: random events of a given duration."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class EventTrigger(Module):
    """Generates random events. After ``initial_delay`` ticks with all outputs 0, one of the
    ``size`` outputs, chosen at random, is set to 1 for ``duration`` ticks; then all outputs
    are 0 for ``timeout`` ticks, and a new event starts. The same output is never chosen twice
    in a row when there is more than one. ``duration`` and ``timeout`` may give one value per
    output (the event's own duration, and the pause after it); a shorter list is extended
    with its last value. A NEXT input with any element above 0 starts a new event at once.
    Durations count exactly: duration 3 means three ticks on (the original kept events on
    one tick longer than their duration and paused one tick longer than timeout)."""

    size = Parameter(1, "the number of outputs (possible events)", type="int")
    initial_delay = Parameter(0, "ticks before the first event", type="int")
    duration = Parameter("100", "ticks each event lasts; one value, or one per output",
                         type="array")
    timeout = Parameter("0", "ticks with all outputs 0 after each event; one value, or one "
                        "per output", type="array")
    seed = Parameter(None, "seed of the random choice; unset (or 0) gives a different run "
                     "every time", type="int")
    NEXT = Input("starts a new event when any element is above 0", optional=True)
    OUTPUT = Output("1 for the current event, 0 elsewhere", size_param="size")

    def init(self):
        self._rng = np.random.default_rng(self.seed or None)
        self._current = -1          # the output that is on, or -1
        self._last = -1             # the last output that was on
        self._left = max(0, self.initial_delay)   # ticks left of the current phase
        self.OUTPUT.fill(0)

    def _per_output(self, values, k):
        values = np.asarray(values).reshape(-1)
        if values.size == 0:
            return 0
        return int(round(float(values[min(k, values.size - 1)])))

    def _start_event(self):
        n = self.OUTPUT.size
        k = int(self._rng.integers(n - 1)) if n > 1 and self._last >= 0 else \
            int(self._rng.integers(n))
        if n > 1 and self._last >= 0 and k >= self._last:
            k += 1                  # skip the last event: a uniform choice among the others
        self.OUTPUT.fill(0)
        self.OUTPUT[k] = 1
        self._current = self._last = k
        self._left = max(1, self._per_output(self.duration, k))

    def tick(self):
        if self.NEXT is not None and np.any(self.NEXT > 0):
            self._start_event()
        elif self._left <= 0:
            pause = self._per_output(self.timeout, self._current) if self._current >= 0 else 0
            if self._current >= 0 and pause > 0:
                self.OUTPUT.fill(0)
                self._current = -1
                self._left = pause
            else:
                self._start_event()
        self._left -= 1
