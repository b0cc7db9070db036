"""What EpiServos, DynamixelController and HeadServos share: a robot's servos from its robot
file, driven on their Dynamixel buses or simulated, with limits, start-up and the safe state.

Units: positions in degrees (180 is a servo's centre), currents in mA, PWM in percent of the
servo's PWM limit.
"""
from __future__ import annotations

import numpy as np

from ikaros.hardware import DeviceError
from ikaros.modules.io._files import model_folder

# what a driver may write (Ikaros 3's DataToWrite names) and the role each writes
WRITABLE = {"Goal Position": "GOAL_POSITION", "Goal Current": "GOAL_CURRENT", "Torque Enable": "TORQUE_ENABLE",
            "Goal PWM": "TORQUE_LIMIT"}
OPERATING_MODE = {"Position": 3, "CurrentPosition": 5}     # e-Manual, X series, "Operating Mode(11)"
SILENT_TICKS = 10
WATCHDOG_SECONDS = 1.0


def robot_of(module, name: str):
    """The robot ``name`` from its file (beside the model, or of this package)."""
    from ikaros.hardware.dynamixel.robot_config import load_robot
    if not str(name).strip():
        raise ValueError("robot is empty: name the robot (a file robots/NAME.json; see docs/robots.md)")
    return load_robot(str(name).strip(), model_folder(module))


def parse_writes(text: str) -> set[str]:
    """The fields of a DataToWrite list (``"Goal Position,Goal Current,Torque Enable"``)."""
    fields = {part.strip() for part in str(text).split(",") if part.strip()}
    unknown = fields - set(WRITABLE)
    if unknown:
        raise ValueError(f"DataToWrite names {', '.join(sorted(unknown))}; it may name "
                         f"{', '.join(WRITABLE)}")
    return fields


def limits(robot, low=None, high=None) -> tuple[np.ndarray, np.ndarray]:
    """Per servo, the position limits in degrees: ``low``/``high`` (one per servo that has
    limits in its robot type, in order) where given, else the robot type's (NaN: none)."""
    lows = np.array([np.nan if s.low is None else s.low for s in robot.servos], float)
    highs = np.array([np.nan if s.high is None else s.high for s in robot.servos], float)
    limited = [k for k, s in enumerate(robot.servos) if s.low is not None]
    for given, target in ((low, lows), (high, highs)):
        if given is None:
            continue
        values = np.asarray(given, float).reshape(-1)
        if values.size != len(limited):
            raise ValueError(f"{values.size} position limits given; the {robot.name} has {len(limited)} "
                             f"servos with limits ({', '.join(robot.servos[k].name for k in limited)})")
        target[limited] = values
    return lows, highs


def latency(module) -> float | None:
    """The module's ``serial_latency`` in ms (None: the bus's default)."""
    return None if module.serial_latency < 0 else float(module.serial_latency)


SERIAL_LATENCY = ("milliseconds the adapters may hold a packet, which sets how long an answer is waited for "
                  "(-1: 16, or 20 on a pseudo-terminal)")


def top_speeds(robot) -> np.ndarray:
    """Each servo's no-load speed in degrees per second (its model's, from its control table)."""
    return np.array([s.table.no_load_rpm * 6.0 for s in robot.servos])


def toward(present: np.ndarray, goal: np.ndarray, most: np.ndarray) -> np.ndarray:
    """``present`` moved toward ``goal`` by at most ``most`` (per element)."""
    return present + np.clip(goal - present, -most, most)


class ChainDriver:
    """A robot's servos for a module: ``simulate`` moves them in the model (``follow``
    computes the next positions from the present, the goals and the tick duration), else
    they are driven on their buses. ``writes`` are the DataToWrite fields."""

    def __init__(self, module, robot, simulate: bool, low: np.ndarray, high: np.ndarray,
                 control_mode: str = "Position", writes: set[str] = frozenset(WRITABLE), follow=None,
                 latency_ms: float | None = None):
        self.module, self.robot, self.simulate = module, robot, bool(simulate)
        self.latency_ms = latency_ms
        self.low, self.high = low, high
        self.control_mode, self.writes = control_mode, set(writes)
        self.follow = follow or (lambda present, goal, dt: toward(present, goal, top_speeds(robot) * dt))
        n = len(robot.servos)
        self.present = np.clip(np.full(n, 180.0), np.nan_to_num(low, nan=-np.inf), np.nan_to_num(high, nan=np.inf))
        self.current = np.zeros(n)
        self.target = np.full(n, np.nan)                  # the last goal (NaN: none yet)
        self.chain = self.watchdog = self.exit_key = None
        self.torque_written: dict[int, float] = {}         # torque enable as last written
        self.silent = np.zeros(n, int)                     # ticks in a row without a reply

    # --- start and end ----------------------------------------------------------------------
    def start(self) -> None:
        if self.simulate:
            return
        from ikaros.hardware import safety
        from ikaros.hardware.dynamixel.chain import ServoChain
        self.chain = ServoChain(self.robot, self.latency_ms)
        try:
            self._set_modes()
            values, missing = self.chain.read(["PRESENT_POSITION"])
            if missing:
                raise DeviceError(f"servo {self.robot.servos[missing[0]].name} of {self.chain} does not answer")
            self.present = values["PRESENT_POSITION"]
            self.chain.write("GOAL_POSITION", dict(enumerate(self.present)))    # hold where they are
        except BaseException:
            self.chain.close()
            self.chain = None
            raise
        self.exit_key = safety.on_exit(str(self.chain), self._safe_state)
        self.watchdog = safety.Watchdog(WATCHDOG_SECONDS, self._safe_state, f"{self.module.path}-watchdog")

    def _set_modes(self) -> None:
        """Each servo that has an Operating Mode in Position, or with CurrentPosition in
        Current-based Position where it measures current. A servo in another mode is switched
        only while its torque is off (the mode is in EEPROM)."""
        wanted = {}
        current = self.chain.has("GOAL_CURRENT")
        for k, servo in enumerate(self.robot.servos):
            if servo.table.role("OPERATING_MODE") is not None:
                wanted[k] = OPERATING_MODE["CurrentPosition" if self.control_mode == "CurrentPosition"
                                           and current[k] else "Position"]
        values, _ = self.chain.read(["OPERATING_MODE", "TORQUE_ENABLE"])
        change = {k: mode for k, mode in wanted.items() if values["OPERATING_MODE"][k] != mode}
        busy = [self.robot.servos[k].name for k in change if values["TORQUE_ENABLE"][k]]
        if busy:
            raise DeviceError(f"servo {', '.join(busy)} of {self.chain} must change its operating mode for "
                              f"ServoControlMode={self.control_mode} but its torque is on; switch it off "
                              "(or power the servos off and on) and start again")
        if change:
            self.chain.write("OPERATING_MODE", change)

    def _safe_state(self) -> None:
        failed = self.chain.safe_state()
        if failed:
            raise RuntimeError(f"servo {', '.join(failed)} of {self.chain} did not answer; the others "
                               "have their torque off")

    def stop(self) -> None:
        from ikaros.hardware import safety
        if self.watchdog is not None:
            self.watchdog.close()
            self.watchdog = None
        try:
            if self.chain is not None:
                self._safe_state()
        except Exception as error:
            self.module.error(str(error))
        finally:
            safety.cancel(self.exit_key)
            self.exit_key = None
            if self.chain is not None:
                self.chain.close()
                self.chain = None

    @property
    def torque_on(self) -> int:
        """How many servos hold a goal: with torque on as last written (in simulation: that
        have had a goal)."""
        if self.simulate:
            return int(np.count_nonzero(np.isfinite(self.target)))
        return sum(1 for v in self.torque_written.values() if v)

    # --- every tick -------------------------------------------------------------------------
    def inputs(self, name: str) -> tuple[np.ndarray, np.ndarray] | None:
        """An input as (values, ready) per servo, or None when it is not connected: an element
        is ready once it holds a value from its source (``Module.input_ready``)."""
        array = getattr(self.module, name, None)
        if array is None:
            return None
        n = len(self.robot.servos)
        values, ready = np.full(n, np.nan), np.zeros(n, bool)
        flat = array.reshape(-1)[:n]
        values[:flat.size] = flat
        ready[:flat.size] = self.module.input_ready(name)[:flat.size] & np.isfinite(flat)
        return values, ready

    def step(self, goal_name="GOAL_POSITION", current_name=None, torque_name=None, pwm_name=None) -> None:
        """One tick: the goals (and currents, torque, PWM) of the named inputs go to the servos
        (clipped to the limits), and ``present`` and ``current`` are read back (or computed)."""
        goal = self.inputs(goal_name)
        torque = self.inputs(torque_name) if torque_name else None
        allowed = np.ones(len(self.robot.servos), bool) if torque is None else torque[1] & (torque[0] != 0)
        if goal is not None:
            ready = goal[1] & allowed
            clipped = np.clip(goal[0], np.nan_to_num(self.low, nan=-np.inf), np.nan_to_num(self.high, nan=np.inf))
            first = ready & np.isnan(self.target)
            self.target = np.where(ready, clipped, self.target)
        else:
            ready = first = np.zeros(len(self.robot.servos), bool)
        if self.simulate:
            dt = self.module.clock.tick_duration
            moving = np.isfinite(self.target) & allowed
            self.present = np.where(moving, self.follow(self.present, np.nan_to_num(self.target), dt), self.present)
            return
        if self.watchdog.kick():                    # made safe while no tick came: take them back
            self.torque_written = {}
            first = ready
        self._write(ready, first, torque, current_name, pwm_name)
        self._read_back()

    def _write(self, ready, first, torque, current_name, pwm_name) -> None:
        current = self.inputs(current_name) if current_name and "Goal Current" in self.writes \
            and self.control_mode == "CurrentPosition" else None
        if current is not None:
            has = self.chain.has("GOAL_CURRENT")
            self.chain.write("GOAL_CURRENT", {k: current[0][k] / 1000.0 for k in np.flatnonzero(current[1] & has)})
        pwm = self.inputs(pwm_name) if pwm_name and "Goal PWM" in self.writes else None
        if pwm is not None:
            self.chain.write("TORQUE_LIMIT", {k: pwm[0][k] / 100.0 for k in np.flatnonzero(pwm[1])})
        if "Torque Enable" in self.writes:
            wanted = ({k: 1.0 for k in np.flatnonzero(first)} if torque is None
                      else {k: float(torque[0][k] != 0) for k in np.flatnonzero(torque[1])})
            changed = {k: v for k, v in wanted.items() if self.torque_written.get(k) != v}
            if changed:
                self.chain.write("TORQUE_ENABLE", changed)
                self.torque_written.update(changed)
        if "Goal Position" in self.writes and ready.any():
            self.chain.write("GOAL_POSITION", {k: self.target[k] for k in np.flatnonzero(ready)})

    def _read_back(self) -> None:
        """Present positions and currents; a servo whose reply is lost keeps its last values,
        and one silent for SILENT_TICKS ticks in a row stops the run."""
        values, missing = self.chain.read(["PRESENT_POSITION", "PRESENT_CURRENT"])
        answered = np.isfinite(values["PRESENT_POSITION"])
        self.present = np.where(answered, values["PRESENT_POSITION"], self.present)
        self.current = np.where(answered, np.nan_to_num(values["PRESENT_CURRENT"]) * 1000.0, self.current)
        self.silent = np.where(answered, 0, self.silent + 1)
        gone = np.flatnonzero(self.silent >= SILENT_TICKS)
        if gone.size:
            raise DeviceError(f"servo {self.robot.servos[gone[0]].name} of {self.chain} does not answer "
                              f"for {SILENT_TICKS} ticks in a row")
