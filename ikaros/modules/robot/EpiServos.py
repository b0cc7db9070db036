"""EpiServos: the Epi humanoid's 19 servos (Ikaros 3)."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter
from ikaros.modules.robot._servo_chain import SERIAL_LATENCY, latency, ChainDriver, limits, parse_writes, robot_of

EPI_ROBOTS = "EpiWhite,EpiGreen,EpiBlue,EpiBlack,EpiRed,EpiOrange"
MIN_LIMITS = "122, 130, 161, 156, 53, 73, 87, 53, 70, 0, 53, 79, 88, 158, 70, 0, 9"
MAX_LIMITS = "237, 240, 202, 193, 281, 281, 263, 202, 342, 360, 281, 290, 264, 316, 343, 360, 343"


class EpiServos(Module):
    """Drives the Epi humanoid's servos, as Ikaros 3 does: element k of every input and output
    is the k-th servo of the robot's type: for an Epi (19) NeckTilt, NeckPan, LeftEye,
    RightEye, PupilLeft, PupilRight, LeftArmJoint1..5, LeftHand, RightArmJoint1..5, RightHand,
    Body; for the torso variant EpiTorso (6) the first six. ``robot`` names a robot file
    (``ikaros/hardware/dynamixel/robots/NAME.json``, or ``robots/NAME.json`` beside the model:
    adding a file adds a robot): its type, which gives the servos' models, ids and buses
    (head, pupil, left arm, right arm, body), and the serial port of each bus. Positions are in
    degrees (180 is a servo's centre), currents in mA, GOAL_PWM in percent of a servo's PWM
    limit. Goals are clipped to MinLimitPosition..MaxLimitPosition (17 values: every servo but
    the pupils, in element order; the pupils keep their own angle limits). With ``simulate``
    nothing is opened: PRESENT_POSITION moves from the previous position toward the goal by at
    most the servo's maximum velocity (its model's no-load speed) times the tick duration, and
    PRESENT_CURRENT is 0. Otherwise every bus is opened at its port, every servo must answer
    as the model its type names, and: at the start each servo's Operating Mode is set to
    Position (ServoControlMode Position) or Current-based Position (CurrentPosition, for the
    servos that measure current; the others stay in Position) — changed only while its torque
    is off, else an error — and its goal to where it is; every tick the fields DataToWrite
    names are written: Goal Current (CurrentPosition only), Goal PWM, Torque Enable (the input,
    or, unconnected, on with a servo's first goal), Goal Position (not to a servo whose
    TORQUE_ENABLE is 0); an input element with no value from its source yet is not written;
    the present positions and currents are read back (a servo whose reply is lost keeps its
    values; one silent 10 ticks in a row stops the run). When the run ends, however it ends,
    and when no tick has come for 1 s, every servo's torque goes off. This project's reading:
    Ikaros 3 gives the interface only; the units, the servo layout (docs/robots.md), the
    operating modes and the simulation's maximum velocity are from the Epi paper and the
    ROBOTIS e-Manual (X and MX(2.0) series, "Operating Mode(11)", "Goal Current(102)", "Goal
    PWM(100)")."""

    robot = Parameter("EpiWhite", "the robot: a file robots/NAME.json (its type and its ports)",
                      type="string", options=EPI_ROBOTS)
    simulate = Parameter(False, "simulate the servos instead of driving them")
    MinLimitPosition = Parameter(MIN_LIMITS, "lowest goal of each servo but the pupils (degrees)", type="array")
    MaxLimitPosition = Parameter(MAX_LIMITS, "highest goal of each servo but the pupils (degrees)", type="array")
    DataToWrite = Parameter("Goal Position,Goal Current,Torque Enable", "the fields written every tick: "
                            "Goal Position, Goal Current, Torque Enable, Goal PWM")
    ServoControlMode = Parameter("Position", "Position, or CurrentPosition (current-based position control: "
                                 "GOAL_CURRENT limits the current)", options="Position,CurrentPosition")

    serial_latency = Parameter(-1.0, SERIAL_LATENCY)

    GOAL_POSITION = Input("goal positions (degrees)")
    GOAL_CURRENT = Input("goal currents (mA; ServoControlMode CurrentPosition)", optional=True)
    TORQUE_ENABLE = Input("1: torque on, 0: off (unconnected: on with a servo's first goal)", optional=True)
    GOAL_PWM = Input("goal PWM (percent of the PWM limit)", optional=True)

    PRESENT_POSITION = Output("present positions (degrees)")
    PRESENT_CURRENT = Output("present currents (mA; 0 for servos without a current sensor, and in simulation)")

    def configure(self):
        self._robot = robot_of(self, self.robot)
        self._writes = parse_writes(self.DataToWrite)
        self._limits = limits(self._robot, self.MinLimitPosition, self.MaxLimitPosition)

    def set_sizes(self):
        for name in ("PRESENT_POSITION", "PRESENT_CURRENT"):
            self.set_output_shape(name, len(self._robot.servos))

    def init(self):
        self._driver = ChainDriver(self, self._robot, self.simulate, *self._limits, str(self.ServoControlMode),
                                   self._writes, latency_ms=latency(self))
        self._driver.start()
        self._show()

    def tick(self):
        self._driver.step("GOAL_POSITION", "GOAL_CURRENT", "TORQUE_ENABLE", "GOAL_PWM")
        self._show()

    def _show(self):
        self.PRESENT_POSITION[:] = self._driver.present
        self.PRESENT_CURRENT[:] = np.nan_to_num(self._driver.current)

    def stop(self):
        driver = getattr(self, "_driver", None)
        if driver is not None:
            driver.stop()
