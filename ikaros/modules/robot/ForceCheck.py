"""ForceCheck: gives way when a servo pushes at its current limit far from its goal (Ikaros 3)."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

AT_LIMIT = 0.95         # a current this close to the limit has reached it


class ForceCheck(Module):
    """Makes a robot in current-based position control compliant, as the compliant-robot models
    of Ikaros 3 use it: for each servo, the current it is given grows with its distance from
    the goal, CurrentOutput = SmoothFactor × the last CurrentOutput + (1 − SmoothFactor) ×
    min(GainConstant × |GoalPositionIn − PresentPosition|, CurrentLimit) (mA, degrees); and
    when a servo is more than ErrorThreshold degrees from its goal while its |PresentCurrent|
    has reached its CurrentLimit (95 % of it) — something holds it back: a hand, an obstacle — its goal
    gives way: GoalPositionOut is its present position; otherwise GoalPositionIn. An element
    that CurrentLimit or PresentCurrent lacks counts as no limit and no current. Both outputs
    have GoalPositionIn's size (19 for the Epi). This project's reading: Ikaros 3 gives the
    interface and the defaults only."""

    GainConstant = Parameter(8.5, "mA of current per degree from the goal")
    SmoothFactor = Parameter(0.7, "how much of the last current is kept each tick, 0..1", range=(0, 1))
    ErrorThreshold = Parameter(10.0, "degrees from the goal beyond which a servo at its current limit gives way")

    GoalPositionIn = Input("goal positions (degrees)")
    PresentPosition = Input("present positions (degrees)")
    PresentCurrent = Input("present currents (mA)")
    CurrentLimit = Input("the highest current of each servo (mA)")

    CurrentOutput = Output("the current each servo is given (mA)", size="GoalPositionIn.size")
    GoalPositionOut = Output("the goals, or where a servo gives way its present position", size="GoalPositionIn.size")

    def _per_servo(self, values: np.ndarray, fill: float) -> np.ndarray:
        out = np.full(self.CurrentOutput.size, fill)
        flat = values.reshape(-1)[:out.size]
        out[:flat.size] = flat
        return out

    def tick(self):
        goal = self.GoalPositionIn.reshape(-1)
        present = self._per_servo(self.PresentPosition, np.nan)
        present = np.where(np.isnan(present), goal, present)
        limit = self._per_servo(self.CurrentLimit, np.inf)
        error = np.abs(goal - present)
        wanted = np.minimum(self.GainConstant * error, limit)
        smooth = float(self.SmoothFactor)
        self.CurrentOutput[:] = smooth * self.CurrentOutput + (1.0 - smooth) * wanted
        at_limit = np.abs(self._per_servo(self.PresentCurrent, 0.0)) >= AT_LIMIT * limit
        held = (error > self.ErrorThreshold) & at_limit
        self.GoalPositionOut[:] = np.where(held, present, goal)
