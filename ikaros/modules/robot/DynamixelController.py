"""DynamixelController: a chain of Dynamixel servos described by a robot file (Ikaros 3)."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter
from ikaros.modules.robot._servo_chain import SERIAL_LATENCY, latency, ChainDriver, limits, robot_of, toward, top_speeds



class DynamixelController(Module):
    """Drives a chain of Dynamixel servos described by a robot file, as Ikaros 3's
    DynamixelController: ``robot`` names the file (``ikaros/hardware/dynamixel/robots/NAME.json``
    or ``robots/NAME.json`` beside the model), whose robot type gives each servo's model (so
    its control table), id and bus, and which gives each bus's port. Element k is the k-th
    servo of the type; ``ServoCount`` above 0 takes the first ServoCount of them (0: all).
    Positions in degrees (180 is a servo's centre), currents in mA, GOAL_PWM in percent of
    the PWM limit. Goals are clipped to the position limits of the robot type or, with
    ``UsePositionLimitParameters``, to MinLimitPosition..MaxLimitPosition (one value per
    servo with limits, in order). ``Simulate`` opens nothing: each tick PRESENT_POSITION moves
    SimulationRate of the way to the goal, at most the servo's maximum velocity (its model's
    no-load speed) times the tick duration; PRESENT_CURRENT is 0. Driven, it does what
    EpiServos does (operating mode per ServoControlMode set at the start while torque is off;
    goal = present position at the start; Goal Current, Goal PWM, Torque Enable and Goal
    Position written every tick, the torque on with a servo's first goal when TORQUE_ENABLE is
    not connected; present positions and currents read back; torque off when the run ends or
    no tick comes for 1 s). STATE has 10 values: 0 simulated (1) or driven (0); 1 servos;
    2 servos with torque on (simulated: that have had a goal); 3 servos that did not answer
    this tick; 4 the largest present current (mA); 5 the largest distance to the goal
    (degrees); 6 goals clipped to a limit; 7 ticks run; 8 buses; 9 the control mode (0
    Position, 1 CurrentPosition). This project's reading: Ikaros 3 gives the interface only; STATE's contents, ServoCount,
    SimulationRate as a fraction of the distance a tick, and the units are this project's."""

    robot = Parameter("", "the robot: a file robots/NAME.json", type="string")
    Simulate = Parameter(False, "simulate the servos instead of driving them")
    ServoCount = Parameter(0, "how many servos of the robot are used, from the first (0: all)", type="int",
                           range=(0, None))
    SimulationRate = Parameter(0.4, "in simulation, the fraction of the distance to the goal moved a tick",
                               range=(0, 1))
    UsePositionLimitParameters = Parameter(False, "clip goals to MinLimitPosition..MaxLimitPosition instead of "
                                           "the robot type's limits")
    MinLimitPosition = Parameter("122, 130, 161, 156, 53, 73, 87, 53, 70, 0, 53, 79, 88, 158, 70, 0, 9",
                                 "lowest goals (degrees), one per servo with limits", type="array")
    MaxLimitPosition = Parameter("237, 240, 202, 193, 281, 281, 263, 202, 342, 360, 281, 290, 264, 316, 343, "
                                 "360, 343", "highest goals (degrees), one per servo with limits", type="array")
    ServoControlMode = Parameter("Position", "Position, or CurrentPosition (current-based position control)",
                                 options="Position,CurrentPosition")

    serial_latency = Parameter(-1.0, SERIAL_LATENCY)

    GOAL_POSITION = Input("goal positions (degrees)")
    GOAL_CURRENT = Input("goal currents (mA; CurrentPosition)", optional=True)
    TORQUE_ENABLE = Input("1: torque on, 0: off (unconnected: on with a servo's first goal)", optional=True)
    GOAL_PWM = Input("goal PWM (percent of the PWM limit)", optional=True)

    PRESENT_POSITION = Output("present positions (degrees)")
    PRESENT_CURRENT = Output("present currents (mA)")
    STATE = Output("the state of the chain (10 values, see the description)", size="10")

    def configure(self):
        from dataclasses import replace
        robot = robot_of(self, self.robot)
        count = int(self.ServoCount)
        if count > len(robot.servos):
            raise ValueError(f"ServoCount is {count}; the robot {robot.name} has {len(robot.servos)} servos")
        self._robot = replace(robot, servos=robot.servos[:count]) if count else robot
        given = (self.MinLimitPosition, self.MaxLimitPosition) if self.UsePositionLimitParameters else (None, None)
        self._limits = limits(self._robot, *given)

    def set_sizes(self):
        for name in ("PRESENT_POSITION", "PRESENT_CURRENT"):
            self.set_output_shape(name, len(self._robot.servos))

    def init(self):
        speeds = top_speeds(self._robot)

        def follow(present, goal, dt):
            return toward(present, goal, np.minimum(abs(goal - present) * float(self.SimulationRate), speeds * dt))
        self._driver = ChainDriver(self, self._robot, self.Simulate, *self._limits, str(self.ServoControlMode),
                                   follow=follow, latency_ms=latency(self))
        self._driver.start()
        self._ticks = 0
        self._show()

    def tick(self):
        self._driver.step("GOAL_POSITION", "GOAL_CURRENT", "TORQUE_ENABLE", "GOAL_PWM")
        self._ticks += 1
        self._show()

    def _show(self):
        driver = self._driver
        self.PRESENT_POSITION[:] = driver.present
        self.PRESENT_CURRENT[:] = np.nan_to_num(driver.current)
        goal = self.inputs_goal()
        clipped = np.isfinite(goal) & (goal != driver.target)
        self.STATE[:] = [float(driver.simulate), len(self._robot.servos),
                         driver.torque_on,
                         int(np.count_nonzero(driver.silent)), float(np.max(np.abs(driver.current), initial=0.0)),
                         float(np.max(np.abs(np.nan_to_num(driver.target - driver.present)), initial=0.0)),
                         int(np.count_nonzero(clipped)), self._ticks, len(set(s.bus for s in self._robot.servos)),
                         float(self.ServoControlMode == "CurrentPosition")]

    def inputs_goal(self) -> np.ndarray:
        goal = self._driver.inputs("GOAL_POSITION")
        return np.where(goal[1], goal[0], np.nan) if goal is not None else np.full(len(self._robot.servos), np.nan)

    def stop(self):
        driver = getattr(self, "_driver", None)
        if driver is not None:
            driver.stop()
