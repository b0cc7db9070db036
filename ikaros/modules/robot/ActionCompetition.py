"""ActionCompetition: actions compete by activation; the winner runs, then is suppressed."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class ActionCompetition(Module):
    """Selects one of ``size`` actions at a time. Each action has an activation level: every
    tick it is pushed by its element of INPUT (a bias; unconnected: 0), relaxes towards
    ``rest`` by the fraction ``passive`` of its distance, and is clipped to ``min``..``max``:
    a ← clip(a + INPUT − passive·(a − rest), min, max). OUTPUT holds the activations. When
    no action is running and at least ``initial_delay`` ticks have passed, the most active
    action wins if its activation is above ``threshold`` (ties: the first): TRIGGER is 1 for
    that action on that tick only, and ACTIVE is 1 while it runs. An action runs for
    ``duration`` ticks (one value, or one per action), or until its element of COMPLETE is
    above 0.5; it then completes: its activation drops by ``completion_bias`` (clipped), and
    the competition is open again on the same tick. The Ikaros 2 parameter ``name`` (the
    actions' names) is not read: ``name`` is the module's own name here. ``passive``,
    ``threshold``, ``completion_bias`` and the ACTIVE output are this implementation's
    choices for what the Ikaros 2 class leaves unstated."""

    size = Parameter(1, "the number of actions")
    initial_delay = Parameter(0, "ticks before the first competition", type="int")
    duration = Parameter("100", "ticks an action runs, one for all or one per action",
                         type="array")
    rest = Parameter(0.0, "the activation that actions relax to")
    min = Parameter(0.0, "the lowest activation")
    max = Parameter(1.0, "the highest activation")
    passive = Parameter(0.1, "fraction of the distance to rest an activation loses per tick")
    threshold = Parameter(0.0, "a winner's activation must be above this")
    completion_bias = Parameter(1.0, "how much a completed action's activation drops")

    INPUT = Input("the bias of each action, added to its activation every tick",
                  optional=True)
    COMPLETE = Input("an element above 0.5 completes that action while it runs",
                     optional=True)

    OUTPUT = Output("the activation of each action", size_param="size")
    TRIGGER = Output("1 for the action that wins, on the tick it wins", size_param="size")
    ACTIVE = Output("1 for the action that is running", size_param="size")

    def init(self):
        n = int(self.size)
        for name in ("INPUT", "COMPLETE"):
            value = getattr(self, name)
            if value is not None and value.size != n:
                raise ValueError(f"{name} has {value.size} elements; size is {n}")
        durations = np.asarray(self.duration, np.float64).reshape(-1)
        if durations.size not in (1, n):
            raise ValueError(f"duration has {durations.size} values; give one, or one per "
                             f"action ({n})")
        self._durations = np.broadcast_to(durations, (n,)).astype(int)
        self.OUTPUT.fill(self.rest)
        self._running = -1
        self._remaining = 0

    def tick(self):
        a = self.OUTPUT
        a -= self.passive * (a - self.rest)
        if self.INPUT is not None:
            a += self.INPUT.reshape(-1)
        np.clip(a, self.min, self.max, out=a)
        self.TRIGGER.fill(0.0)
        if self._running >= 0:
            self._remaining -= 1
            done = self.COMPLETE is not None and self.COMPLETE.reshape(-1)[self._running] > 0.5
            if self._remaining <= 0 or done:
                a[self._running] = max(a[self._running] - self.completion_bias, self.min)
                self._running = -1
        if self._running < 0 and self.clock.tick >= self.initial_delay:
            winner = int(np.argmax(a))
            if a[winner] > self.threshold:
                self._running = winner
                self._remaining = int(self._durations[winner])
                self.TRIGGER[winner] = 1.0
        self.ACTIVE.fill(0.0)
        if self._running >= 0:
            self.ACTIVE[self._running] = 1.0
