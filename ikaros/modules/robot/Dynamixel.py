"""Dynamixel: ROBOTIS Dynamixel servos on a serial bus."""
from __future__ import annotations

import math

import numpy as np

from ikaros.hardware import DeviceError
from ikaros.module import Input, Module, Output, Parameter
from ikaros.modules.robot._dynamixel_build import describe, elements, first_found
from ikaros.modules.robot._dynamixel_report import state_table
from ikaros.modules.robot._dynamixel_writes import NEEDS_TORQUE, SETTINGS, SettingsWriter, ramp

PRESENT = ["PRESENT_POSITION", "PRESENT_SPEED", "PRESENT_LOAD", "PRESENT_VOLTAGE", "PRESENT_TEMPERATURE",
           "PRESENT_CURRENT"]
ANGLE_FACTOR = {"degrees": 1.0, "radians": math.pi / 180.0, "tau": 1.0 / 360.0}
ERROR_BITS = 8


class Dynamixel(Module):
    """Drives ROBOTIS Dynamixel servos on one serial bus (TTL or RS-485) through the ROBOTIS
    dynamixel-sdk: AX-12/AX-18, MX-28/64/106 (Protocol 1.0 or 2.0), XL-320 and the X-430 and
    X-540 series. The servos are ``servo_id`` or, when it is empty, those that answer a scan
    of ids 0..``max_servo_id`` with Protocol 1.0 and then 2.0 (``protocol`` can fix one; a bus
    that mixes the two is refused); ``number_of_servos`` above 0 says how many the scan must
    find (fewer is an error at load; of more, the lowest ids are used: this project's reading,
    the reference names the parameter only). With ``index_mode=direct`` (the default, as in
    Ikaros 2) element i of every input and output is the servo whose id is i: the arrays have
    max id + 1 elements (of ``servo_id``, or of the servos found), and those with no servo are
    unused (outputs read 0). With ``indirect`` element i is the i-th servo of ``servo_id`` in
    the order listed (or of the scan, in id order), and the arrays have one element per servo
    (a listed servo that is left out keeps its element, unused). ``size`` above 0 forces the
    number of elements; a servo whose element would lie outside it is an error at load (the
    reference describes ``size`` only as forcing the array size, so this refusal is this
    project's choice).
    Positions are absolute angles in ``angle_unit`` with 180° (π, 0.5 tau) at a servo's centre:
    raw 512 of the 300° series, raw 2048 of the 4096-step series. MOVING_SPEED and
    TORQUE_LIMIT are fractions of the full scale (speed 1 is about 114 rpm; 0 means the
    servo's own top speed), PRESENT_SPEED and PRESENT_LOAD signed fractions, GOAL_TORQUE a
    fraction of the current (or torque) limit, voltage in volts, temperature in °C, current in
    amperes; gains and GOAL_ACCELERATION are raw control-table values.
    Start-up, as Ikaros 2: when the run starts each servo's torque limit is written 0 and its
    goal position its present position (so a Protocol 1.0 servo, whose torque a goal switches
    on, holds with no force); for the first ``start_up_delay`` ticks nothing is sent at all
    (the outputs keep the values read at the start); then the torque limit written ramps over
    ``torque_up_delay`` ticks from 0 to the TORQUE_LIMIT input, multiplier (tick −
    start_up_delay) / torque_up_delay, then 1 (ticks counted from the module's first, 0). In
    an Ikaros 2 file TORQUE_LIMIT must be connected, as there; in an Ikaros 3 file it may be
    left out, and the ramp then ends at the limit each servo held at the start. Each tick the
    inputs are written in Ikaros 2's order: TORQUE_ENABLE, LED, D_GAIN, I_GAIN, P_GAIN,
    GOAL_POSITION, MOVING_SPEED, TORQUE_LIMIT, GOAL_TORQUE, GOAL_ACCELERATION, one sync write
    each; GOAL_POSITION and MOVING_SPEED are not written to a servo whose TORQUE_ENABLE input
    is 0 (writing them switches a Protocol 1.0 servo's torque on). With ``optimize`` (the
    default; the reference gives none) a value is sent only when it differs from the last one
    written; otherwise every connected input is sent every tick. The present values are read
    back (one sync read in Protocol 2.0, one bulk read for MX servos in 1.0, else one read per
    servo; ``feedback`` chooses all of them, the position only, or none). Additions that keep
    a robot still: an input element that has not yet received a value from its source
    (``Module.input_ready``) is not written; a servo's goal is first written on the first
    tick its GOAL_POSITION element is not 0, and its torque is switched on then (or by
    TORQUE_ENABLE when that is connected); goals are clipped to each servo's angle limits.
    Heat, as Ikaros 2: when a servo's present temperature is above ``max_temperature`` (60
    °C; 0: not watched) the state of every servo is printed, the servos are put in the safe
    state and the run stops with an error naming the servo and its temperature (the
    temperature is read with ``feedback`` all or position, not none). ERRORS has one row per
    servo with the bits of its last status packet (Protocol 1.0 error bits; in 2.0 the error
    number's bits and bit 7 the hardware alert). When the run ends for any reason, and when no
    tick has come for ``watchdog`` seconds (paused, stopped, hung), every servo that answers
    is put in ``safe_state``: torque off, or hold (goal = present position); when ticks come
    again after torque off (or on ``resume``), the servos start again as at start-up (torque
    limit 0, goal = present position, the ramp over ``torque_up_delay`` ticks), so a servo
    moved by hand meanwhile does not jump back.
    Real buses lose packets: a status packet that does not come is asked for again, a servo
    whose reply is still missing keeps its last feedback for that tick and counts in
    MISSED_REPLIES, and only a servo silent for ``silent_ticks`` ticks in a row stops the run,
    with an error naming the servo, the bus and the register ("Present Position, address
    132"); the others are made safe. The command ``safe_state`` goes to the safe state at once
    and keeps the servos there (feedback is still read) until the command ``resume``; then the
    next goal takes them back as at start-up. ``device="sim:dynamixel?ids=1-3"`` runs the
    simulator in this process (docs/robots.md). Differences from Ikaros 2: the safe state is
    torque off rather than a torque-limit ramp that left torque enabled; ERRORS has 8 columns
    (one per bit); protocol, safe_state, watchdog, feedback, serial_latency, silent_ticks and
    MISSED_REPLIES are additions; max_servo_id is 12 in an Ikaros 2 file (as there) and 32 in
    an Ikaros 3 file."""

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
    number_of_servos = Parameter(0, "how many servos a scan must find (0: any number; of more, the lowest "
                                 "ids are used)", type="int", range=(0, None))
    angle_unit = Parameter("degrees", "unit of positions", options="degrees/radians/tau")
    max_servo_id = Parameter(12, "the highest id a scan pings (12 in an Ikaros 2 file, 32 in an Ikaros 3 file)",
                             default_v3=32)
    protocol = Parameter("auto", "protocol version (auto: ping with 1.0, then 2.0)", options="auto/1/2")
    start_up_delay = Parameter(10, "ticks at the start in which nothing is sent", type="int", range=(0, None))
    torque_up_delay = Parameter(100, "ticks over which the torque limit then ramps from 0 to TORQUE_LIMIT",
                                type="int", range=(0, None))
    max_temperature = Parameter(60.0, "°C: a servo above it stops the run in the safe state (0: not watched)",
                                range=(0, None))
    optimize = Parameter(True, "send only the values that changed since they were last written")
    safe_state = Parameter("torque_off", "what the servos do when the run ends or the watchdog fires",
                           options="torque_off/hold")
    watchdog = Parameter(1.0, "seconds without a tick before the servos are put in the safe state (0: never)")
    feedback = Parameter("all", "what is read back every tick: all present values (position, speed, load, "
                         "voltage, temperature, current), only the position (and the temperature, when "
                         "watched), or none", options="all/position/none")
    serial_latency = Parameter(-1.0, "milliseconds the adapter may hold a packet (-1: 16, or 20 on a "
                               "pseudo-terminal)")
    silent_ticks = Parameter(10, "ticks in a row a servo may miss its status packet before the run "
                             "stops (a lost packet is asked for again first)", type="int", range=(1, None))

    TORQUE_ENABLE = Input("1: torque on, 0: off, and no goal or speed is written (unconnected: on with "
                          "the first goal)", optional=True)
    LED = Input("LED on (1) or off (0); XL-320: colour 0..7", optional=True)
    D_GAIN = Input("derivative gain (raw)", optional=True)
    I_GAIN = Input("integral gain (raw)", optional=True)
    P_GAIN = Input("proportional gain (raw)", optional=True)
    GOAL_POSITION = Input("goal angles (0: no goal yet)", optional=True)
    MOVING_SPEED = Input("speed, a fraction of about 114 rpm (0: the servo's top speed)", optional=True)
    TORQUE_LIMIT = Input("torque limit, 0..1, reached through the start-up ramp (required in an Ikaros 2 "
                         "file)", optional=True)
    GOAL_TORQUE = Input("goal torque, -1..1 of the limit (MX-64/106, current-controlled X)", optional=True)
    GOAL_ACCELERATION = Input("goal (profile) acceleration (raw)", optional=True)

    FEEDBACK_TORQUE_ENABLE = Output("torque enable as last written (or read at start)")
    FEEDBACK_LED = Output("LED as last written")
    FEEDBACK_D_GAIN = Output("derivative gain")
    FEEDBACK_I_GAIN = Output("integral gain")
    FEEDBACK_P_GAIN = Output("proportional gain")
    FEEDBACK_GOAL_POSITION = Output("goal angle as last written")
    FEEDBACK_MOVING_SPEED = Output("moving speed as last written")
    FEEDBACK_TORQUE_LIMIT = Output("torque limit as last written (the ramped value during the ramp)")
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
        try:
            if not wanted and self.number_of_servos > 0:
                tables = first_found(tables, int(self.number_of_servos), int(self.max_servo_id), described)
            self._tables = dict(sorted(tables.items()))
            self._ids = list(self._tables)
            self._size, self._index = elements(str(self.index_mode), int(self.size), self._ids, wanted or self._ids)
        except ValueError:
            self._close_simulator()
            raise

    def set_sizes(self):
        if self.dialect != "3" and not self.connected("TORQUE_LIMIT"):
            self._close_simulator()
            raise ValueError('the input TORQUE_LIMIT is not connected: an Ikaros 2 file must connect it '
                             '(the torque limit ramps up to it at the start)')
        for name in self._ik_outputs:
            self.set_output_shape(name, (self._size, ERROR_BITS) if name == "ERRORS" else self._size)

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
            self.print(describe(group.bus, group.tables, self.print_info == "full"))
        self._angle = ANGLE_FACTOR[self.angle_unit]
        self._writer = SettingsWriter(group, bool(self.optimize), self._published)
        start = group.read(SETTINGS)
        for role, values in start.items():
            self._writer.remember(role, values)
            self._published(role, values)
        self._full_torque = dict(start["TORQUE_LIMIT"])          # the ramp's end without an input
        limits = group.read(["MIN_POSITION", "MAX_POSITION"])
        self._limits = {i: (limits["MIN_POSITION"].get(i), limits["MAX_POSITION"].get(i)) for i in self._ids}
        self._errors: dict[int, int] = {}
        self._silent = {ident: 0 for ident in self._ids}       # ticks in a row without a reply
        self._last: dict[str, dict[int, float]] = {}           # the last present values read
        self._halted = False
        self._ticks = 0
        self._start_again(ramp_from=int(self.start_up_delay))
        if self.feedback == "none" and self.max_temperature > 0:
            self.warning('feedback="none" reads no temperature: max_temperature is not watched')
        self._read_feedback()
        self._exit_key = safety.on_exit(f"the Dynamixel bus {group.bus}", self._safe_state)
        self._watchdog = safety.Watchdog(float(self.watchdog), self._safe_state, f"{self.path}-watchdog")

    def _published(self, role: str, values: dict[int, float]) -> None:
        self._publish("FEEDBACK_" + role, values, self._angle if role == "GOAL_POSITION" else 1.0)

    def _publish(self, output: str, values: dict[int, float], factor: float = 1.0) -> None:
        array = getattr(self, output)
        for position, ident in enumerate(self._ids):
            if ident in values:
                array[self._index[position]] = values[ident] * factor

    def _inputs(self, name: str) -> dict[int, float] | None:
        """Per servo, the input's value where it has one from its source (None: unconnected)."""
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

    def _start_again(self, ramp_from: int) -> None:
        """Ikaros 2's start-up, at the start and after the safe state torque off: torque limit
        0 and goal = present position (a Protocol 1.0 servo, whose torque a goal switches on,
        holds with no force); the torque limit ramps up from tick ``ramp_from``; the next goal
        or TORQUE_ENABLE takes the servos back."""
        self._commanded = {ident: False for ident in self._ids}
        self._writer.forget("TORQUE_ENABLE")
        self._writer.forget("GOAL_POSITION")
        self._writer.write("TORQUE_LIMIT", {ident: 0.0 for ident in self._ids})
        present = self._group.read_available(["PRESENT_POSITION"])[0]["PRESENT_POSITION"]
        self._writer.write("GOAL_POSITION", present)
        self._ramp_from = ramp_from

    def _after_safe_state(self) -> None:
        """The servos were made safe: with torque off they start again as at start-up; held,
        the next goal takes them on."""
        if self.safe_state == "torque_off":
            self._start_again(ramp_from=self._ticks)
        else:
            self._commanded = {ident: False for ident in self._ids}

    def tick(self):
        if self._watchdog.kick():                        # the servos were made safe: start again
            self._after_safe_state()
        tick, self._ticks = self._ticks, self._ticks + 1
        if self._halted:
            if self.feedback != "none":
                self._read_feedback(self._feedback_roles())
            self._report_errors()
            return
        if tick < self.start_up_delay:
            return                                       # as Ikaros 2: no instruction at all
        self._write_inputs(tick)
        if self.feedback != "none":
            self._read_feedback(self._feedback_roles())
            self._check_heat()
        self._report_errors()

    def _write_inputs(self, tick: int) -> None:
        values = {role: self._inputs(role) for role in SETTINGS}
        torque_input = values["TORQUE_ENABLE"]
        allowed = set(self._ids) if torque_input is None else {i for i, v in torque_input.items() if v != 0}
        goals = {}
        for ident, value in (values["GOAL_POSITION"] or {}).items():
            if value != 0.0 and math.isfinite(value) and ident in allowed:
                goals[ident] = self._clip_to_limits(ident, value / self._angle)
        newly = [ident for ident in goals if not self._commanded[ident]]
        values["TORQUE_ENABLE"] = {i: 1.0 for i in newly} if torque_input is None else torque_input
        values["GOAL_POSITION"] = goals
        for role in NEEDS_TORQUE[1:]:
            values[role] = {i: v for i, v in (values[role] or {}).items() if i in allowed}
        values["TORQUE_LIMIT"] = self._torque_limits(values["TORQUE_LIMIT"], tick)
        for role in SETTINGS:
            if values[role]:
                self._writer.write(role, values[role])
        for ident in goals:
            self._commanded[ident] = True

    def _torque_limits(self, inputs: dict[int, float] | None, tick: int) -> dict[int, float]:
        """The torque limits of this tick: the input (or without one, the limit at the start;
        0 where the input has no value yet) times the ramp's multiplier."""
        factor = ramp(tick, self._ramp_from, int(self.torque_up_delay))
        targets = self._full_torque if inputs is None else {i: inputs.get(i, 0.0) for i in self._ids}
        return {ident: value * factor for ident, value in targets.items()}

    def _clip_to_limits(self, ident: int, degrees: float) -> float:
        low, high = self._limits[ident]
        if low is None or low == high:         # wheel mode
            return degrees
        return min(max(degrees, low), high)

    def _feedback_roles(self) -> list[str]:
        if self.feedback == "all":
            return PRESENT
        return ["PRESENT_POSITION", "PRESENT_TEMPERATURE"] if self.max_temperature > 0 else ["PRESENT_POSITION"]

    def _read_feedback(self, roles: list[str] = PRESENT) -> None:
        """Read the present values back. A servo whose reply is lost keeps its last values and
        counts in MISSED_REPLIES; one silent for ``silent_ticks`` ticks in a row stops the run."""
        values, missing = self._group.read_available(roles)
        for role in roles:
            self._last.setdefault(role, {}).update(values[role])
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

    def _check_heat(self) -> None:
        """Above ``max_temperature``: print every servo's state, go to the safe state, stop."""
        limit = float(self.max_temperature)
        hot = {i: t for i, t in self._last.get("PRESENT_TEMPERATURE", {}).items() if t > limit} if limit > 0 else {}
        if not hot:
            return
        ident = max(hot, key=hot.get)
        written = {role: {i: self._group.tables[i].role(role).to_value(raw)
                          for i, raw in self._writer.raw[role].items()}
                   for role in ("TORQUE_ENABLE", "TORQUE_LIMIT")}
        self.print(f"servo {ident} is too hot; the state of every servo on {self._group.bus}:\n"
                   + state_table(self._group.tables, {**self._last, **written}))
        self._halted = True
        try:
            self._safe_state()
            done = f"the servos are in the safe state ({self.safe_state})"
        except RuntimeError as error:
            done = str(error)
        raise DeviceError(f"servo {ident} on {self._group.bus} is at {hot[ident]:.0f} °C, above "
                          f"max_temperature ({limit:g} °C): {done}")

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
            if self._group is not None:
                self._after_safe_state()
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
