"""One simulated Dynamixel servo: its control-table memory and its dynamics.

What the servo does follows the ROBOTIS e-Manual's control tables (AX-12A and MX-28 for
Protocol 1.0, XM430-W350 and the other X series for 2.0), sections "Torque Enable", "Goal
Position", "Torque Limit" (Protocol 1.0; "Goal PWM" for the X series) and "Shutdown":

* It moves only with its torque on: the present position follows the goal at the moving
  speed (or the model's no-load speed), and only while its torque limit exceeds the load it
  must hold; with a torque limit of 0 it gives no torque at all ("Torque Limit": 0 means no
  torque is used) and stays where it is.
* A servo of the Protocol 1.0 series (AX, MX 1.0: ``goal_enables_torque`` in its table)
  switches its torque on when its Goal Position or Moving Speed is written, as their
  firmware does. The e-Manual's control tables do not say so; Ikaros 2's Dynamixel class
  relies on it (it writes no goal to a servo whose torque the model keeps off). The X series
  switch torque on only through Torque Enable.
* Load rises with an external load and while moving; the temperature rises under load and
  falls back to the servo's surroundings (:meth:`SimulatedServo.set_temperature` sets both);
  the overload error (a load above a torque limit above 0 for 0.3 s), the overheating error
  (above Temperature Limit) and the angle-limit error (a goal outside the limits) are raised
  as a real servo raises them, and overload and overheating switch torque off until a reboot.
"""
from __future__ import annotations

from ikaros.hardware.dynamixel import protocol as p
from ikaros.hardware.dynamixel.control_table import ControlTable

AMBIENT_TEMPERATURE = 30.0
HEATING_PER_SECOND = 4.0        # degrees C per second at full load
COOLING_PER_SECOND = 0.05       # fraction of the excess over the surroundings lost per second
OVERLOAD_SECONDS = 0.3          # load above the torque limit this long trips the overload error
MOVING_LOAD = 0.08              # load fraction while moving


class SimulatedServo:
    """One servo: its control table memory and its dynamics."""

    def __init__(self, ident: int, table: ControlTable, baud_rate: int, position: float | None = None):
        self.table = table
        self.memory = table.initial_memory()
        self._put("ID", ident)
        self._put("BAUD_RATE", table.baud_code(baud_rate))
        present = table.role("PRESENT_POSITION")
        goal = table.role("GOAL_POSITION")
        raw = present.to_raw(position) if position is not None else present.field.default
        self.position = float(raw)
        self._write_field(present.field, raw)
        self._write_field(goal.field, raw)
        self.surroundings = AMBIENT_TEMPERATURE
        self.temperature = AMBIENT_TEMPERATURE
        self.external_load = 0.0        # fraction of the maximum torque, signed
        self.load = 0.0
        self.overload_time = 0.0
        self.alarms = 0                 # Protocol 1.0 error bits that persist
        self.registered: tuple[int, bytes] | None = None

    # --- memory ---------------------------------------------------------------------------
    @property
    def ident(self) -> int:
        return self.memory[self.table.role("ID").field.address]

    @property
    def baud_rate(self) -> int:
        code = self.memory[self.table.role("BAUD_RATE").field.address]
        return self.table.baud_rates.get(code, -1)

    def raw(self, role: str) -> int:
        f = self.table.role(role).field
        return int.from_bytes(self.memory[f.address:f.address + f.size], "little")

    def value(self, role: str) -> float:
        return self.table.role(role).to_value(self.raw(role))

    def _put(self, role: str, raw: int) -> None:
        entry = self.table.role(role)
        if entry is not None:
            self._write_field(entry.field, raw)

    def _write_field(self, f, raw: int) -> None:
        self.memory[f.address:f.address + f.size] = (int(raw) & ((1 << 8 * f.size) - 1)).to_bytes(f.size, "little")

    @property
    def torque(self) -> bool:
        return self.raw("TORQUE_ENABLE") != 0

    @property
    def torque_limit(self) -> float:
        """The torque it may use, a fraction of its maximum (Torque Limit, or Goal PWM)."""
        return self.value("TORQUE_LIMIT") if self.table.role("TORQUE_LIMIT") else 1.0

    def set_temperature(self, celsius: float) -> None:
        """The servo and its surroundings are at ``celsius`` (it stays there unless loaded)."""
        self.surroundings = self.temperature = float(celsius)
        self._put("PRESENT_TEMPERATURE", int(round(self.temperature)))

    def read(self, address: int, length: int) -> tuple[int, bytes]:
        """(error, data) of a read."""
        if length < 1 or address + length > len(self.memory):
            return self._range_error(), b""
        return 0, bytes(self.memory[address:address + length])

    def write(self, address: int, data: bytes) -> int:
        """Write ``data`` at ``address``; returns the error of the status packet."""
        protocol = self.table.protocol
        if not data or address + len(data) > len(self.memory):
            return self._range_error()
        fields = [f for f in self.table.fields.values()
                  if f.address < address + len(data) and address < f.address + f.size]
        if any(f.access == "R" for f in fields):
            return p.P2_ACCESS if protocol == 2 else p.P1_RANGE
        if protocol == 2 and self.torque and address < self.table.role("TORQUE_ENABLE").field.address:
            return p.P2_ACCESS              # EEPROM is locked while torque is on
        goal = self.table.role("GOAL_POSITION").field
        if goal.address <= address < goal.address + goal.size and address + len(data) >= goal.address + goal.size:
            raw = int.from_bytes(data[goal.address - address:goal.address - address + goal.size], "little")
            if not self._within_limits(raw):
                return p.P2_DATA_LIMIT if protocol == 2 else p.P1_ANGLE_LIMIT
        self.memory[address:address + len(data)] = data
        if self.table.goal_enables_torque and any(
                self.table.role(role).field in fields for role in ("GOAL_POSITION", "MOVING_SPEED")):
            self._put("TORQUE_ENABLE", 1)
        if self.raw("TORQUE_ENABLE") and self.alarms & (p.P1_OVERLOAD | p.P1_OVERHEATING):
            self._put("TORQUE_ENABLE", 0)   # a tripped servo keeps torque off until rebooted
            return self.alarms if protocol == 1 else p.P2_RESULT_FAIL
        return 0

    def _range_error(self) -> int:
        return p.P2_ACCESS if self.table.protocol == 2 else p.P1_RANGE

    def _within_limits(self, raw: int) -> bool:
        low, high = self.raw("MIN_POSITION"), self.raw("MAX_POSITION")
        if self.table.protocol == 1 and low == 0 and high == 0:
            return True                     # wheel mode
        if self.table.role("GOAL_POSITION").signed == "twos" and raw >= 1 << 31:
            raw -= 1 << 32
        return low <= raw <= high

    def status_error(self) -> int:
        """The error byte every status packet carries besides the instruction's own error."""
        if self.table.protocol == 1:
            return self.alarms
        hardware = self.table.role("HARDWARE_ERROR")
        return p.P2_ALERT if hardware is not None and self.raw("HARDWARE_ERROR") else 0

    def reboot(self) -> None:
        self.alarms = 0
        self.overload_time = 0.0
        self._put("HARDWARE_ERROR", 0)
        self._put("TORQUE_ENABLE", 0)

    def factory_reset(self) -> None:
        """The control table's factory values, keeping the id."""
        kept = self.ident
        self.memory = self.table.initial_memory()
        self._put("ID", kept)
        self.position = float(self.raw("PRESENT_POSITION"))

    # --- dynamics -------------------------------------------------------------------------
    def advance(self, dt: float) -> None:
        """Move the servo on by ``dt`` seconds."""
        table = self.table
        goal_role, present_role = table.role("GOAL_POSITION"), table.role("PRESENT_POSITION")
        degrees_per_raw = abs(present_role.scale)
        speed_raw = self.raw("MOVING_SPEED") & 0x3FF if table.protocol == 1 else self.raw("MOVING_SPEED")
        rpm = speed_raw * table.rpm_per_speed_unit if speed_raw else table.no_load_rpm
        rpm = min(rpm, table.no_load_rpm)
        step = rpm * 6.0 / degrees_per_raw * dt              # raw units this dt
        limit = self.torque_limit
        driving = self.torque and limit > abs(self.external_load)   # it has torque to spare
        moving = False
        velocity = 0.0
        if driving:
            goal = present_role.to_raw(goal_role.to_value(self.raw("GOAL_POSITION")))
            error = goal - self.position
            moving = abs(error) > 0.5
            self.position = float(goal) if abs(error) <= step else self.position + step * (1 if error > 0 else -1)
            velocity = (step / dt if moving and dt > 0 else 0.0) * (1 if error > 0 else -1)
        wanted = self.external_load + (MOVING_LOAD if moving else 0.0) * (1 if velocity >= 0 else -1)
        self.load = max(-limit, min(limit, wanted)) if self.torque else 0.0
        self.temperature += (HEATING_PER_SECOND * self.load ** 2
                             - COOLING_PER_SECOND * (self.temperature - self.surroundings)) * dt
        if self.torque and limit > 0 and abs(self.external_load) > limit:
            self.overload_time += dt
        else:
            self.overload_time = 0.0
        if self.overload_time > OVERLOAD_SECONDS:
            self._trip(p.P1_OVERLOAD, p.HW_OVERLOAD)
        if self.temperature > self.raw("TEMPERATURE_LIMIT"):
            self._trip(p.P1_OVERHEATING, p.HW_OVERHEATING)
        self._publish(velocity * degrees_per_raw / 6.0, moving)

    def _trip(self, p1_bit: int, hardware_bit: int) -> None:
        self.alarms |= p1_bit
        if self.table.role("HARDWARE_ERROR") is not None:
            self._put("HARDWARE_ERROR", self.raw("HARDWARE_ERROR") | hardware_bit)
        self._put("TORQUE_ENABLE", 0)

    def _publish(self, rpm: float, moving: bool) -> None:
        table = self.table
        self._write_field(table.role("PRESENT_POSITION").field, int(round(self.position)))
        speed = table.role("PRESENT_SPEED")
        full_scale_rpm = 1.0 / speed.scale * table.rpm_per_speed_unit
        self._write_field(speed.field, speed.to_raw(rpm / full_scale_rpm))
        load = table.role("PRESENT_LOAD")
        self._write_field(load.field, load.to_raw(max(-1.0, min(1.0, self.load))))
        current = table.role("PRESENT_CURRENT")
        if current is not None and current.field is not load.field:
            self._write_field(current.field, current.to_raw(self.load * 2.0))
        self._put("PRESENT_TEMPERATURE", int(round(self.temperature)))
        self._put("MOVING", int(moving))
