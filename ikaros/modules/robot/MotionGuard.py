"""MotionGuard: a safety filter between motion commands and the servos."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class MotionGuard(Module):
    """Limits motion commands (INPUT) against the present position of the robot (REFERENCE),
    element by element, so that a servo is never told to go far from where it is. Each tick
    the target is INPUT clipped to ``input_limit_min``..``input_limit_max`` (one value for all
    elements or one per element; empty: no limit). The step from REFERENCE towards the target
    is at most ``max_speed`` (position units per tick) and changes from the previous tick's
    step by at most ``max_acceleration`` (0: no limit), slowing down in time to stop at the
    target; OUTPUT = REFERENCE + step. The guard holds (OUTPUT stays at the position where
    holding began, HOLD is 1) while INPUT is missing — NaN, or all zeros, as an input before
    its source has produced anything — and after INPUT jumps by more than ``max_jump`` in one
    tick (0: never), until INPUT has been steady for ``settle_ticks`` ticks; then it moves
    towards the target at the limited speed again. While REFERENCE is all zeros (the position
    is not known yet) OUTPUT is 0, which a Dynamixel module takes as "no goal yet". The
    Ikaros 2 class had the limiting commented out and only copied INPUT to OUTPUT;
    max_acceleration, max_jump, settle_ticks and HOLD are additions."""

    max_speed = Parameter(0.1, "largest step from REFERENCE per tick (position units)")
    max_acceleration = Parameter(0.0, "largest change of the step per tick (0: no limit)")
    input_limit_min = Parameter("", "smallest allowed target, one for all or one per element", type="array")
    input_limit_max = Parameter("", "largest allowed target, one for all or one per element", type="array")
    max_jump = Parameter(0.0, "an INPUT change per tick larger than this makes the guard hold (0: never)")
    settle_ticks = Parameter(10, "ticks INPUT must be steady before a hold ends")

    INPUT = Input("the motion command (goal positions)")
    REFERENCE = Input("the present positions of the robot")
    OUTPUT = Output("the limited command", size_set="INPUT,REFERENCE")
    HOLD = Output("1 while the guard holds", size="1")

    def init(self):
        if self.INPUT.size != self.REFERENCE.size:
            raise ValueError(f"INPUT has {self.INPUT.size} elements and REFERENCE {self.REFERENCE.size}: "
                             "they must be equal")
        n = self.INPUT.size
        self._input = self.INPUT.reshape(-1)
        self._reference = self.REFERENCE.reshape(-1)
        self._output = self.OUTPUT.reshape(-1)
        self._step = np.zeros(n)
        self._last_input = None
        self._held: np.ndarray | None = None
        self._steady = 0

    def _limit(self, name: str, fill: float) -> np.ndarray:
        values = np.asarray(getattr(self, name), dtype=np.float64).reshape(-1)
        if values.size == 0:
            return np.full(self._input.size, fill)
        if values.size == 1:
            return np.full(self._input.size, values[0])
        if values.size != self._input.size:
            raise ValueError(f"{name} has {values.size} values; give one, or one per element ({self._input.size})")
        return values

    def tick(self):
        reference = self._reference.astype(np.float64)
        command = self._input.astype(np.float64)
        if not np.any(reference):
            self._output[...] = 0.0
            self._step[...] = 0.0
            return
        missing = not np.all(np.isfinite(command)) or not np.any(command)
        jumped = (self.max_jump > 0 and self._last_input is not None and not missing
                  and np.any(np.abs(command - self._last_input) > self.max_jump))
        self._last_input = None if missing else command
        if missing or jumped:
            if self._held is None:
                self._held = reference.copy()
            self._steady = 0
            self._hold()
            return
        if self._held is not None:
            self._steady += 1
            if self._steady < self.settle_ticks:
                self._hold()
                return
            self._held = None
        target = np.clip(command, self._limit("input_limit_min", -np.inf), self._limit("input_limit_max", np.inf))
        wanted = target - reference
        step = np.clip(wanted, -self.max_speed, self.max_speed)
        if self.max_acceleration > 0:
            a = self.max_acceleration
            braking = np.sqrt(2.0 * a * np.abs(wanted))       # fast enough to stop at the target
            step = np.clip(step, -braking, braking)
            step = np.clip(step, self._step - a, self._step + a)
        self._step = step
        self._output[...] = reference + step
        self.HOLD[0] = 0.0

    def _hold(self):
        self._step[...] = 0.0
        self._output[...] = self._held
        self.HOLD[0] = 1.0
