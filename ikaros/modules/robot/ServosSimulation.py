"""ServosSimulation: servos under current-based position control, simulated (Ikaros 3)."""
import numpy as np

from ikaros.module import Input, Module, Output

STALL_CURRENT = 5200.0          # mA: MX-106(2.0) stall current at 12 V (e-Manual, MX-106(2.0) specifications)
TOP_SPEED = 270.0               # degrees per second: MX-106(2.0) no-load speed at 12 V (45 rpm)
FULL_CURRENT_ERROR = 10.0       # degrees from the goal at which the controller asks for the stall current


class ServosSimulation(Module):
    """Simulates servos in current-based position control, as the compliant-robot models of
    Ikaros 3 use it in place of the robot: each servo's position controller asks for a current
    in proportion to its distance from GoalPosition (the stall current at 10° and beyond),
    limited to the smaller of |GoalCurrent| and CurrentLimit (mA); the servo turns at a speed
    in proportion to the current it gets (its no-load speed at the stall current), without
    overshooting the goal. PresentPosition (degrees, 180 at the start) and PresentCurrent (mA,
    signed with the direction) have one element per element of GoalPosition; an element that
    GoalCurrent or CurrentLimit lacks is not limited by it. This project's reading: Ikaros 3
    gives the interface only; the servo is an MX-106(2.0) of the Epi's arms (stall current
    5.2 A, no-load speed 45 rpm, ROBOTIS e-Manual), with no load, inertia or friction."""

    GoalCurrent = Input("the current each servo may use (mA)", flatten=True)
    CurrentLimit = Input("the highest current of each servo (mA)", flatten=True)
    GoalPosition = Input("goal positions (degrees)", flatten=True)

    PresentPosition = Output("present positions (degrees)", size="GoalPosition.size")
    PresentCurrent = Output("present currents (mA)", size="GoalPosition.size")

    def init(self):
        self.PresentPosition[:] = 180.0

    def _per_servo(self, values: np.ndarray, fill: float) -> np.ndarray:
        out = np.full(self.PresentPosition.size, fill)
        flat = values.reshape(-1)[:out.size]
        out[:flat.size] = flat
        return out

    def tick(self):
        goal = self.GoalPosition.reshape(-1)
        present = self.PresentPosition
        allowed = np.minimum(np.abs(self._per_servo(self.GoalCurrent, STALL_CURRENT)),
                             self._per_servo(self.CurrentLimit, STALL_CURRENT))
        error = goal - present
        current = np.clip(STALL_CURRENT * error / FULL_CURRENT_ERROR, -allowed, allowed)
        step = TOP_SPEED * current / STALL_CURRENT * self.clock.tick_duration
        present += np.where(np.abs(step) >= np.abs(error), error, step)
        self.PresentCurrent[:] = current
