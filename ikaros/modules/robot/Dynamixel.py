"""Dynamixel: ROBOTIS Dynamixel servos on a serial bus."""
from __future__ import annotations

import math

import numpy as np

from ikaros.hardware import DeviceError
from ikaros.module import Input, Module, Output, Parameter

SETTINGS = ["TORQUE_ENABLE", "LED", "D_GAIN", "I_GAIN", "P_GAIN", "GOAL_POSITION", "MOVING_SPEED",
            "TORQUE_LIMIT", "GOAL_TORQUE", "GOAL_ACCELERATION"]
PRESENT = ["PRESENT_POSITION", "PRESENT_SPEED", "PRESENT_LOAD", "PRESENT_VOLTAGE", "PRESENT_TEMPERATURE",
           "PRESENT_CURRENT"]
ANGLE_FACTOR = {"degrees": 1.0, "radians": math.pi / 180.0, "tau": 1.0 / 360.0}
ERROR_BITS = 8


class Dynamixel(Module):
    """Drives ROBOTIS Dynamixel servos on one serial bus (TTL or RS-485) through the ROBOTIS
    dynamixel-sdk: AX-12/AX-18, MX-28/64/106 (Protocol 1.0 or 2.0), XL-320 and the X-430 and
    X-540 series. The servos are ``servo_id`` or, when it is empty, those that answer a scan
    of ids 0..``max_servo_id`` with Protocol 1.0 and then 2.0 (``protocol`` can fix one; a bus
    that mixes the two is refused). With ``index_mode=direct`` (the default, as in Ikaros 2)
    element i of every input and output is the servo whose id is i: the arrays have max id + 1
    elements (of ``servo_id``, or of the servos found), and those with no servo are unused
    (outputs read 0). With ``indirect`` element i
    is the i-th servo of ``servo_id`` in the order listed (or of the scan, in id order), and
    the arrays have one element per servo (a listed servo that is left out keeps its element,
    unused). ``size`` above 0 forces the number of elements; a servo whose element would lie
    outside it is an error at load (the reference describes ``size`` only as forcing the array
    size, so this refusal is this project's choice).
    Positions are absolute angles in ``angle_unit`` with 180° (π, 0.5 tau) at a servo's centre:
    raw 512 of the 300° series, raw 2048 of the 4096-step series. MOVING_SPEED and
    TORQUE_LIMIT are fractions of the full scale (speed 1 is about 114 rpm; 0 means the
    servo's own top speed), PRESENT_SPEED and PRESENT_LOAD signed fractions, GOAL_TORQUE a
    fraction of the current (or torque) limit, voltage in volts, temperature in °C, current in
    amperes; gains and GOAL_ACCELERATION are raw control-table values. Every tick the inputs
    are written (GOAL_POSITION in one sync write, the other inputs only when they change) and
    the present values read back (one sync read in Protocol 2.0, one bulk read for MX servos in 1.0,
    else one read per servo; ``feedback`` chooses all of them, the
    position only, or none). Nothing moves at start-up: an input element that has not yet
    received a value from its source (``Module.input_ready``) is not written, and
    a servo's goal is first written on the first tick its GOAL_POSITION element is not 0, and
    its torque is switched on then (or by TORQUE_ENABLE when that is connected); goals are
    clipped to each servo's angle limits. ERRORS has one row per servo with the bits of its
    last status packet (Protocol 1.0 error bits; in 2.0 the error number's bits and bit 7 the
    hardware alert). When the run ends for any reason, and when no tick has come for
    ``watchdog`` seconds (paused, stopped, hung), every servo that answers is put in
    ``safe_state``: torque off, or hold (goal = present position). Real buses lose packets: a
    status packet that does not come is asked for again, a servo whose reply is still missing
    keeps its last feedback for that tick and counts in MISSED_REPLIES, and only a servo
    silent for ``silent_ticks`` ticks in a row stops the run, with an error naming the servo,
    the bus and the register ("Present Position, address 132"); the others are made safe. The command ``safe_state`` goes to the
    safe state at once and keeps the servos there (feedback is still read) until the command
    ``resume``; then the next goal takes them back as at start-up. ``device="sim:dynamixel?ids=1-3"``
    runs the simulator in this process (docs/robots.md). Differences from Ikaros 2: the safe
    state is torque off rather than a torque-limit ramp that left torque enabled; ERRORS has
    8 columns (one per bit); protocol, max_servo_id, safe_state, watchdog, feedback,
    serial_latency, silent_ticks and MISSED_REPLIES are additions."""

    device = Parameter("/dev/cu.usbserial-A7005Lxn", "the serial device of the bus (e.g. /dev/ttyUSB0), "
                       "or sim:dynamixel?ids=...&protocol=... for the simulator")
    baud_rate = Parameter(1000000, "baud rate of the bus")
    print_info = Parameter("minimal", "what to print about the servos found", options="none/minimal/full")
    servo_id = Parameter("", "the ids of the servos (empty: scan 0..max_servo_id)", type="array")
    strict_servo_id = Parameter(False, "stop with an error when a servo of servo_id does not answer "
                                "(otherwise it is left out with a warning)")
    index_mode = Parameter("direct", "direct: element i is the servo with id i; indirect: element i is the "
                           "i-th servo of servo_id (or of the scan)", options="direct/indirect")
    size = Parameter(0, "the number of elements of every input and output (0: max id + 1 with direct, "
                     "the number of servos with indirect)", type="int")
    angle_unit = Parameter("degrees", "unit of positions", options="degrees/radians/tau")
    max_servo_id = Parameter(32, "the highest id a scan pings")
    protocol = Parameter("auto", "protocol version (auto: ping with 1.0, then 2.0)", options="auto/1/2")
    safe_state = Parameter("torque_off", "what the servos do when the run ends or the watchdog fires",
                           options="torque_off/hold")
    watchdog = Parameter(1.0, "seconds without a tick before the servos are put in the safe state (0: never)")
    feedback = Parameter("all", "what is read back every tick: all present values (position, speed, load, "
                         "voltage, temperature, current), only the position, or none", options="all/position/none")
    serial_latency = Parameter(-1.0, "milliseconds the adapter may hold a packet (-1: 16, or 20 on a "
                               "pseudo-terminal)")
    silent_ticks = Parameter(10, "ticks in a row a servo may miss its status packet before the run "
                             "stops (a lost packet is asked for again first)", type="int", range=(1, None))

    TORQUE_ENABLE = Input("1: torque on, 0: off (unconnected: on with the first goal)", optional=True)
    LED = Input("LED on (1) or off (0); XL-320: colour 0..7", optional=True)
    D_GAIN = Input("derivative gain (raw)", optional=True)
    I_GAIN = Input("integral gain (raw)", optional=True)
    P_GAIN = Input("proportional gain (raw)", optional=True)
    GOAL_POSITION = Input("goal angles (0: no goal yet)", optional=True)
    MOVING_SPEED = Input("speed, a fraction of about 114 rpm (0: the servo's top speed)", optional=True)
    TORQUE_LIMIT = Input("torque limit, 0..1", optional=True)
    GOAL_TORQUE = Input("goal torque, -1..1 of the limit (MX-64/106, current-controlled X)", optional=True)
    GOAL_ACCELERATION = Input("goal (profile) acceleration (raw)", optional=True)

    FEEDBACK_TORQUE_ENABLE = Output("torque enable as last written (or read at start)")
    FEEDBACK_LED = Output("LED as last written")
    FEEDBACK_D_GAIN = Output("derivative gain")
    FEEDBACK_I_GAIN = Output("integral gain")
    FEEDBACK_P_GAIN = Output("proportional gain")
    FEEDBACK_GOAL_POSITION = Output("goal angle as last written")
    FEEDBACK_MOVING_SPEED = Output("moving speed as last written")
    FEEDBACK_TORQUE_LIMIT = Output("torque limit as last written")
    FEEDBACK_PRESENT_POSITION = Output("present angle")
    FEEDBACK_PRESENT_SPEED = Output("present speed, signed fraction")
    FEEDBACK_PRESENT_LOAD = Output("present load, signed fraction")
    FEEDBACK_PRESENT_VOLTAGE = Output("present voltage (V)")
    FEEDBACK_PRESENT_TEMPERATURE = Output("present temperature (°C)")
    FEEDBACK_PRESENT_CURRENT = Output("present current (A); 0 for models without a current sensor")
    FEEDBACK_GOAL_TORQUE = Output("goal torque as last written")
    FEEDBACK_GOAL_ACCELERATION = Output("goal acceleration as last written")
    ERRORS = Output("the error bits of each servo's last status packet, one row per servo")
    MISSED_REPLIES = Output("how many status packets of each servo never came (after a retry), since the start")

    # --- build ------------------------------------------------------------------------------
    def configure(self):
        # The bus is scanned here (the servos found give the output sizes) and given back;
        # init opens it again, so a model whose build fails later leaves no port open.
        from ikaros.hardware.dynamixel.servos import open_bus, release_bus
        from ikaros.hardware.simulators import open_device_string
        self._simulator = None
        self._group = None
        self._watchdog = None
        self._exit_key = None
        device, self._simulator = open_device_string(str(self.device))
        wanted = [int(i) for i in np.asarray(self.servo_id).reshape(-1)] or None
        self._latency = None if self.serial_latency < 0 else float(self.serial_latency)
        try:
            bus, tables = open_bus(device, int(self.baud_rate), self.protocol, wanted, int(self.max_servo_id),
                                   self._latency)
            described = str(bus)
            self._protocol = bus.protocol
            release_bus(bus)
        except Exception:
            self._close_simulator()
            raise
        self._device_path = device
        if wanted:
            missing = [i for i in wanted if i not in tables]
            if missing and (self.strict_servo_id or len(missing) == len(wanted)):
                self._close_simulator()
                raise ValueError(f"servo {', '.join(map(str, missing))} on {described} does not answer")
            if missing:
                self.warning(f"servo {', '.join(map(str, missing))} on {described} does not answer; left out")
        self._tables = dict(sorted(tables.items()))
        self._ids = list(self._tables)
        size, self._index = self._elements(wanted or self._ids)
        for name in self._ik_outputs:
            self.set_output_shape(name, (size, ERROR_BITS) if name == "ERRORS" else size)

    def _elements(self, order: list[int]) -> tuple[int, np.ndarray]:
        """The array size and the element of each servo (in id order) for ``index_mode``:
        its id (direct), or its place in ``order``, the listed or scanned ids (indirect)."""
        if self.index_mode == "direct":
            element = {ident: ident for ident in self._ids}
            natural = max(order) + 1
        else:
            element = {ident: order.index(ident) for ident in self._ids}
            natural = len(order)
        size = int(self.size) if int(self.size) > 0 else natural
        outside = [ident for ident in self._ids if element[ident] >= size]
        if outside:
            self._close_simulator()
            raise ValueError(f"size=\"{int(self.size)}\" leaves no element for servo "
                             f"{', '.join(map(str, outside))} (index_mode=\"{self.index_mode}\" "
                             f"needs at least {natural})")
        return size, np.array([element[ident] for ident in self._ids], dtype=int)

    def _describe(self, bus, tables) -> str:
        models = {}
        for ident, table in tables.items():
            models.setdefault(table.model, []).append(ident)
        text = f"{len(tables)} servos on {bus}: " + "; ".join(f"{m} {ids}" for m, ids in models.items())
        if self.print_info == "full":
            for ident, table in tables.items():
                text += f"\n  id {ident}: {table.model} (model number {table.model_number}, {table.series})"
        return text

    # --- run --------------------------------------------------------------------------------
    def init(self):
        from ikaros.hardware.dynamixel.servos import ServoGroup, acquire_bus
        bus = acquire_bus(self._device_path, int(self.baud_rate), self._protocol, self._latency)
        self._group = group = ServoGroup(bus, self._tables)
        try:
            self._start(group)
        except BaseException:
            self.stop()                         # init cleans up after itself
            raise

    def _start(self, group) -> None:
        from ikaros.hardware import safety
        if self.print_info != "none":
            self.print(self._describe(group.bus, group.tables))
        self._angle = ANGLE_FACTOR[self.angle_unit]
        self._written: dict[str, dict[int, float]] = {role: {} for role in SETTINGS}
        start = group.read(SETTINGS)
        for role, values in start.items():
            self._written[role].update(values)
            self._publish("FEEDBACK_" + role, values, self._angle if role == "GOAL_POSITION" else 1.0)
        limits = group.read(["MIN_POSITION", "MAX_POSITION"])
        self._limits = {i: (limits["MIN_POSITION"].get(i), limits["MAX_POSITION"].get(i)) for i in self._ids}
        self._errors: dict[int, int] = {}
        self._silent = {ident: 0 for ident in self._ids}       # ticks in a row without a reply
        self._halted = False
        self._start_again()                    # torque is written explicitly, whatever it was
        self._read_feedback()
        self._exit_key = safety.on_exit(f"the Dynamixel bus {group.bus}", self._safe_state)
        self._watchdog = safety.Watchdog(float(self.watchdog), self._safe_state, f"{self.path}-watchdog")

    def _publish(self, output: str, values: dict[int, float], factor: float = 1.0) -> None:
        array = getattr(self, output)
        for position, ident in enumerate(self._ids):
            if ident in values:
                array[self._index[position]] = values[ident] * factor

    def _inputs(self, name: str) -> dict[int, float] | None:
        array = getattr(self, name)
        if array is None:
            return None
        flat = array.reshape(-1)
        ready = self.input_ready(name)
        out = {}
        for position, ident in enumerate(self._ids):
            element = self._index[position]
            if element < flat.size and ready[element]:
                out[ident] = float(flat[element])
        return out

    def _start_again(self) -> None:
        """After a safe state: the next goal or TORQUE_ENABLE takes the servos back, as at start-up."""
        self._commanded = {ident: False for ident in self._ids}
        self._written["TORQUE_ENABLE"] = {ident: -1.0 for ident in self._ids}

    def tick(self):
        if self._watchdog.kick():                        # the servos were made safe: start again
            self._start_again()
        if self._halted:
            if self.feedback != "none":
                self._read_feedback(PRESENT if self.feedback == "all" else ["PRESENT_POSITION"])
            self._report_errors()
            return
        group = self._group
        goals = self._inputs("GOAL_POSITION")
        newly = []
        if goals is not None:
            commanded = {}
            for ident, value in goals.items():
                if value != 0.0 and np.isfinite(value):
                    if not self._commanded[ident]:
                        newly.append(ident)
                        self._commanded[ident] = True
                    commanded[ident] = self._clip_to_limits(ident, value / self._angle)
            if commanded:
                group.write("GOAL_POSITION", commanded)
                self._written["GOAL_POSITION"].update(commanded)
                self._publish("FEEDBACK_GOAL_POSITION", commanded, self._angle)
        torque = self._inputs("TORQUE_ENABLE")
        if torque is None and newly:
            torque = {ident: 1.0 for ident in newly}
        for role in SETTINGS:
            values = torque if role == "TORQUE_ENABLE" else None if role == "GOAL_POSITION" else self._inputs(role)
            if values:
                self._write_changed(role, values)
        if self.feedback != "none":
            self._read_feedback(PRESENT if self.feedback == "all" else ["PRESENT_POSITION"])
        self._report_errors()

    def _clip_to_limits(self, ident: int, degrees: float) -> float:
        low, high = self._limits[ident]
        if low is None or low == high:         # wheel mode
            return degrees
        return min(max(degrees, low), high)

    def _write_changed(self, role: str, values: dict[int, float]) -> None:
        written = self._written[role]
        changed = {i: v for i, v in values.items() if np.isfinite(v) and written.get(i) != v
                   and self._group.has(i, role)}
        if not changed:
            return
        if role == "TORQUE_ENABLE":
            turning_on = [i for i, v in changed.items() if v and not self._commanded[i]]
            if turning_on:                              # hold where it is: no jump to an old goal
                present = self._group.read_available(["PRESENT_POSITION"], turning_on)[0]["PRESENT_POSITION"]
                self._group.write("GOAL_POSITION", present)
                changed = {i: v for i, v in changed.items() if i in present or i not in turning_on}
        self._group.write(role, changed)
        written.update(changed)
        self._publish("FEEDBACK_" + role, changed)

    def _read_feedback(self, roles: list[str] = PRESENT) -> None:
        """Read the present values back. A servo whose reply is lost keeps its last values and
        counts in MISSED_REPLIES; one silent for ``silent_ticks`` ticks in a row stops the run."""
        values, missing = self._group.read_available(roles)
        for role in roles:
            self._publish("FEEDBACK_" + role, values[role], self._angle if role == "PRESENT_POSITION" else 1.0)
        for position, ident in enumerate(self._ids):
            if ident in missing:
                self._silent[ident] += 1
                self.MISSED_REPLIES[self._index[position]] += 1
            else:
                self._silent[ident] = 0
        gone = [ident for ident in missing if self._silent[ident] >= self.silent_ticks]
        if gone:
            ident = gone[0]
            raise DeviceError(f"servo {ident} on {self._group.bus} does not answer (reading {missing[ident]}) "
                              f"for {self._silent[ident]} ticks in a row")

    def _report_errors(self) -> None:
        errors = self._group.bus.errors
        for position, ident in enumerate(self._ids):
            bits = errors.get(ident, 0)
            if bits != self._errors.get(ident, 0):
                self._errors[ident] = bits
                self.ERRORS[self._index[position]] = [(bits >> k) & 1 for k in range(ERROR_BITS)]
                if bits:
                    self.warning(f"servo {ident} on {self._group.bus}: {self._group.error_text(ident, bits)}")

    def command(self, name, x=0, y=0, value=None):
        if name == "safe_state" and self._group is not None:
            self._halted = True
            self._safe_state()
        elif name == "resume":
            self._halted = False
            self._start_again()
        else:
            raise ValueError(f"unknown command '{name}' (safe_state, resume)")

    # --- the end ----------------------------------------------------------------------------
    def _safe_state(self) -> None:
        failures = self._group.safe_state(self.safe_state)
        if failures:
            names = ", ".join(str(i) for i in sorted(failures))
            raise RuntimeError(f"servo {names} on {self._group.bus} did not answer; "
                               f"the others are in the safe state ({self.safe_state})")

    def stop(self):
        from ikaros.hardware import safety
        from ikaros.hardware.dynamixel.servos import release_bus
        if self._watchdog is not None:
            self._watchdog.close()
        group, self._group = self._group, None
        try:
            if group is not None and self._exit_key is not None:
                self._group = group
                self._safe_state()
        except Exception as error:
            self.error(str(error))
        finally:
            self._group = None
            safety.cancel(self._exit_key)
            self._exit_key = None
            if group is not None:
                release_bus(group.bus)
            self._close_simulator()

    def _close_simulator(self) -> None:
        if self._simulator is not None:
            self._simulator.stop()
            self._simulator = None
