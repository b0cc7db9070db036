"""ServoControlTuning: a step sequence for tuning one servo of an Epi (Ikaros 3)."""
import json
import os

import numpy as np

from ikaros.module import Module, Output, Parameter

SERVOS = ["NeckTilt", "NeckPan", "LeftEye", "RightEye", "PupilLeft", "PupilRight", "ArmJoint1", "ArmJoint2",
          "ArmJoint3", "ArmJoint4", "ArmJoint5", "Hand", "Body"]
# the element of MinLimitPosition/MaxLimitPosition (every Epi servo but the pupils) of each choice
LIMIT_ELEMENT = {"NeckTilt": 0, "NeckPan": 1, "LeftEye": 2, "RightEye": 3, "ArmJoint1": 4, "ArmJoint2": 5,
                 "ArmJoint3": 6, "ArmJoint4": 7, "ArmJoint5": 8, "Hand": 9, "Body": 16}
DEGREES_PER_STEP = 360.0 / 4096          # the 4096-step series (e-Manual, "Goal Position": 0.088° a unit)
TRANSITION_SECONDS = 1.0


class ServoControlTuning(Module):
    """Gives one servo of an Epi a step sequence for tuning its control, as Ikaros 3's
    ServoControlTuning: ``Servo`` chooses it (the arm joints and hand are the left arm's),
    ServoParameters are (start position, first position, second position in degrees; first
    and last goal current in mA; profile velocity and profile acceleration, raw, 0: the
    servo's own). Position is (goal position in degrees, the same in the servo's raw steps,
    4096 a turn), Current is (goal current in mA, the current reached at the end of the
    sweep); the goal is clipped to MinLimitPosition..MaxLimitPosition of the servo (raw steps,
    17 values: every servo but the pupils, whose goal is not clipped). Without RunSequence the
    servo is held at the start position with the first current. With RunSequence, it makes
    NumberTransitions moves of 1 s each, alternating between the first and the second position,
    while the goal current rises evenly from the first to the last current (so the least
    current that still reaches the goal can be read off the servo's answer), and then returns
    to the start. While Save is on, the parameters, the servo and the robot are written once
    to ServoControlTuning_ROBOT_SERVO.json (in the user-data folder, or beside the model).
    This project's reading: Ikaros 3 gives the interface and the defaults only."""

    ServoParameters = Parameter("180,200,180,0,1000,0,0", "start, first and second position (degrees), first "
                                "and last current (mA), profile velocity and acceleration (raw)", type="array")
    MinLimitPosition = Parameter("1300, 1750, 1830, 1780, 600, 800, 1000, 600, 800, 0, 600, 900, 1000, 1800, 800, "
                                 "0, 100", "lowest goal of each servo but the pupils (raw steps)", type="array")
    MaxLimitPosition = Parameter("2700, 2500, 2300, 2200, 3200, 3200, 3000, 2300, 3900, 4095, 3200, 3300, 3000, "
                                 "3600, 3900, 4095, 3900", "highest goal of each servo but the pupils (raw steps)",
                                 type="array")
    Servo = Parameter("NeckTilt", "the servo tuned", options=SERVOS)
    robot = Parameter("", "the robot (written into the saved file)", type="string",
                      options="EpiGray,EpiBlack,EpiWhite,EpiBlue,EpiYellow,EpiRed,EpiOrange,EpiGreen")
    Save = Parameter(False, "write the parameters to a file (once each time it is switched on)")
    RunSequence = Parameter(False, "run the step sequence")
    NumberTransitions = Parameter(10, "moves of the sequence", type="int", range=(1, None))

    Position = Output("goal position: degrees, raw steps", size="2")
    Current = Output("goal current and the sweep's last current (mA)", size="2")

    def init(self):
        self._step = 0
        self._saved = False
        self._show()

    def _parameters(self) -> np.ndarray:
        values = np.zeros(7)
        given = np.asarray(self.ServoParameters, float).reshape(-1)[:7]
        values[:given.size] = given
        return values

    def tick(self):
        self._step = self._step + 1 if self.RunSequence else 0
        if self.Save and not self._saved:
            self._save()
        self._saved = bool(self.Save)
        self._show()

    def _show(self) -> None:
        start, first, second, low, high = self._parameters()[:5]
        ticks = max(1, round(TRANSITION_SECONDS / self.clock.tick_duration)) if self.clock.tick_duration > 0 else 1
        move = (self._step - 1) // ticks + 1 if self._step else 0           # 1..NumberTransitions while running
        count = int(self.NumberTransitions)
        if 1 <= move <= count:
            goal = first if move % 2 else second
            current = low + (high - low) * move / count
        else:
            goal, current = start, low
        raw = self._clip(goal / DEGREES_PER_STEP)
        self.Position[:] = [raw * DEGREES_PER_STEP, raw]
        self.Current[:] = [current, high]

    def _clip(self, raw: float) -> float:
        element = LIMIT_ELEMENT.get(str(self.Servo))
        if element is None:
            return raw
        low = np.asarray(self.MinLimitPosition, float).reshape(-1)
        high = np.asarray(self.MaxLimitPosition, float).reshape(-1)
        if element >= min(low.size, high.size):
            return raw
        return float(np.clip(raw, low[element], high[element]))

    def _save(self) -> None:
        from ikaros.modules.io._files import resolve
        name = f"ServoControlTuning_{str(self.robot) or 'robot'}_{self.Servo}.json"
        path = resolve(self, name, write=True)
        start, first, second, low, high, velocity, acceleration = self._parameters()
        element = LIMIT_ELEMENT.get(str(self.Servo))
        limits = None if element is None else [float(np.asarray(self.MinLimitPosition, float).reshape(-1)[element]),
                                               float(np.asarray(self.MaxLimitPosition, float).reshape(-1)[element])]
        with open(path, "w", encoding="utf-8") as f:
            json.dump({"robot": str(self.robot), "servo": str(self.Servo), "positions": [start, first, second],
                       "currents": [low, high], "profile_velocity": velocity, "profile_acceleration": acceleration,
                       "limits_raw": limits, "transitions": int(self.NumberTransitions)}, f, indent=2)
        self.print(f"saved the tuning of {self.Servo} to {os.path.basename(path)}")
