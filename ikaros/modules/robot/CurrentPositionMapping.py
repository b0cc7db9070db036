"""CurrentPositionMapping: learns the current each position takes, moving through the range (Ikaros 3)."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

REACHED = 2.0               # degrees: a goal counts as reached this close
BIN = 1.0                   # degrees: the width of a position of the map
MARGIN = 1.2                # the current given is the learned one times this
STILL = 0.1                 # degrees: servos that moved less in STILL_SECONDS have stopped
STILL_SECONDS = 1.0


class CurrentPositionMapping(Module):
    """Maps, for the servos of a compliant robot in current-based position control, the
    current each position takes, and drives them through their range to learn it, as the
    compliant-robot models of Ikaros 3 do. The mapped servos are the first ones, as many as
    MinLimits has values (for RobotType Torso: neck tilt and neck pan). They visit
    NumberTransitions positions spread evenly over MinLimits..MaxLimits (degrees), one after
    the other, then back, and so on: GoalPosition is the position of the present transition
    for the mapped servos and the present position for the others; a transition ends when
    every mapped servo is within 2° of its goal, or when none has moved more than 0.1° in the
    last second (held back, or at a limit of the robot). Meanwhile each mapped servo's |PresentCurrent|
    (mA) is averaged per degree of its PresentPosition (from the first tick on); GoalCurrent is
    1.2 × the current mapped at the servo's goal (at the mapped degree nearest it), and for the
    other servos their present current. This project's reading: Ikaros 3 gives the interface and
    the defaults only; the evenly spread positions, the 2° and the margin are this project's;
    RobotType is kept (the mapped servos follow from MinLimits)."""

    NumberTransitions = Parameter(4, "how many positions are visited across the range (at least 2)",
                                  range=(2, None))
    MinLimits = Parameter("114,153 ", "the lowest position of each mapped servo (degrees)", type="array")
    MaxLimits = Parameter("237,219", "the highest position of each mapped servo (degrees)", type="array")
    RobotType = Parameter("Torso", "the robot (Torso: the head's neck tilt and pan are mapped)")

    PresentPosition = Input("present positions (degrees)")
    PresentCurrent = Input("present currents (mA)")

    GoalPosition = Output("goal positions (degrees)", size="PresentPosition.size")
    GoalCurrent = Output("goal currents (mA)", size="PresentCurrent.size")

    def init(self):
        low = np.asarray(self.MinLimits, float).reshape(-1)
        high = np.asarray(self.MaxLimits, float).reshape(-1)
        if low.size != high.size or low.size > self.PresentPosition.size:
            raise ValueError(f"MinLimits has {low.size} values and MaxLimits {high.size}: give one each per "
                             f"mapped servo (at most {self.PresentPosition.size})")
        steps = np.linspace(0.0, 1.0, int(self.NumberTransitions))
        self._stops = low[None, :] + (high - low)[None, :] * steps[:, None]     # one row a transition
        self._mapped = low.size
        self._stop, self._direction = 0, 1
        still = max(1, round(STILL_SECONDS / self.clock.tick_duration)) if self.clock.tick_duration > 0 else 1
        self._recent: list[np.ndarray] = []            # the mapped servos' positions, last STILL_SECONDS
        self._still_ticks = still
        self._sum: list[dict[int, float]] = [{} for _ in range(low.size)]
        self._count: list[dict[int, int]] = [{} for _ in range(low.size)]

    def tick(self):
        present = self.PresentPosition.reshape(-1)
        current = np.abs(self.PresentCurrent.reshape(-1))
        n = self._mapped
        for k in range(n):
            if k < current.size:
                degree = int(round(present[k] / BIN))
                self._sum[k][degree] = self._sum[k].get(degree, 0.0) + current[k]
                self._count[k][degree] = self._count[k].get(degree, 0) + 1
        self._recent = (self._recent + [present[:n].copy()])[-self._still_ticks - 1:]
        stopped = len(self._recent) > self._still_ticks and np.all(np.ptp(self._recent, axis=0) <= STILL)
        if stopped or np.all(np.abs(present[:n] - self._stops[self._stop]) <= REACHED):
            self._next_stop()
            self._recent = []
        self.GoalPosition[:] = present
        self.GoalPosition[:n] = self._stops[self._stop]
        self.GoalCurrent[:] = current
        for k in range(min(n, self.GoalCurrent.size)):
            self.GoalCurrent[k] = MARGIN * self._mapped_current(k, self._stops[self._stop][k])

    def _next_stop(self) -> None:
        last = len(self._stops) - 1
        if not 0 <= self._stop + self._direction <= last:
            self._direction = -self._direction
        self._stop += self._direction

    def _mapped_current(self, servo: int, position: float) -> float:
        """The mean current learned at the mapped degree nearest ``position``."""
        learned = self._count[servo]
        if not learned:
            return 0.0
        degree = min(learned, key=lambda d: abs(d * BIN - position))
        return self._sum[servo][degree] / learned[degree]
