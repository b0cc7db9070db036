"""A virtual Dynamixel bus on a pseudo-terminal, answering Protocol 1.0 or 2.0 byte for byte.

Each simulated servo has the real control table of its model (``control_table``), answers
ping, read, write, reg write/action, sync write, sync read and bulk read/write (as its
protocol allows), and moves: its present position follows the goal position at the moving
speed (or the model's no-load speed), load rises with an external load and while moving,
temperature rises under load, and the overload, overheating and angle-limit errors are
raised as a real servo raises them (overload and overheating switch torque off).

A servo answers only while the driver's port runs at the servo's baud rate (read from the
terminal settings the driver made), so a wrong baud rate looks as it does on a real bus.
With ``line_time=True`` every packet takes the time it would take on the wire at that rate,
and each status packet comes after the servo's Return Delay Time.

Faults for tests: :meth:`silence` (a servo stops answering), :meth:`lose` (the next status
packets are lost), :meth:`corrupt` (the next status packets have a broken checksum or CRC), :meth:`answer_as` (a servo answers with a wrong id),
and ``disconnect()`` (the bus disappears).
"""
from __future__ import annotations

import termios
import threading
import time

from ikaros.hardware.dynamixel import protocol as p
from ikaros.hardware.dynamixel.control_table import ControlTable, table_for_model
from ikaros.hardware.pty_device import PtyDevice, sleep_until

DEFAULT_MODEL = {1: "AX-12A", 2: "XM430-W350"}
AMBIENT_TEMPERATURE = 30.0
HEATING_PER_SECOND = 4.0        # degrees C per second at full load
COOLING_PER_SECOND = 0.05       # fraction of the excess over ambient lost per second
OVERLOAD_SECONDS = 0.3          # load above the torque limit this long trips the overload error
MOVING_LOAD = 0.08              # load fraction while moving

_SPEEDS = {getattr(termios, name): int(name[1:]) for name in dir(termios)
           if name.startswith("B") and name[1:].isdigit()}


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
        moving = False
        if self.torque:
            goal = present_role.to_raw(goal_role.to_value(self.raw("GOAL_POSITION")))
            error = goal - self.position
            moving = abs(error) > 0.5
            self.position = float(goal) if abs(error) <= step else self.position + step * (1 if error > 0 else -1)
            velocity = (step / dt if moving and dt > 0 else 0.0) * (1 if error > 0 else -1)
        else:
            velocity = 0.0
        limit = self.value("TORQUE_LIMIT") if table.role("TORQUE_LIMIT") else 1.0
        self.load = (self.external_load + (MOVING_LOAD if moving else 0.0) * (1 if velocity >= 0 else -1)) \
            if self.torque else 0.0
        self.temperature += (HEATING_PER_SECOND * self.load ** 2
                             - COOLING_PER_SECOND * (self.temperature - AMBIENT_TEMPERATURE)) * dt
        if self.torque and abs(self.external_load) > limit:
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


class VirtualDynamixelBus(PtyDevice):
    """Simulated servos on one pseudo-terminal; ``servos`` maps id -> model name."""

    name = "dynamixel"

    def __init__(self, servos: dict[int, str], protocol: int = 2, baud_rate: int = 1000000,
                 line_time: bool = False, positions: dict[int, float] | None = None):
        super().__init__()
        if protocol not in (1, 2):
            raise ValueError(f"protocol must be 1 or 2, not {protocol}")
        self.protocol = protocol
        self.line_time = line_time
        self.lock = threading.RLock()
        self.servos: dict[int, SimulatedServo] = {}
        for ident, model in servos.items():
            table = table_for_model(model)
            if table.protocol != protocol:
                raise ValueError(f"the {model} speaks Protocol {table.protocol}.0, the bus {protocol}.0")
            self.servos[ident] = SimulatedServo(ident, table, baud_rate, (positions or {}).get(ident))
        self._reader = p.PacketReader(protocol)
        self._silent: set[int] = set()
        self._corrupt = 0
        self._lost = 0
        self._aliases: dict[int, int] = {}
        self._last_update = time.perf_counter()
        self._bus_free_at = 0.0
        self.packets = 0                # instruction packets received (for tests and benchmarks)

    # --- faults and the world ---------------------------------------------------------------
    def silence(self, *idents: int, silent: bool = True) -> None:
        """Servos stop answering (or, with ``silent=False``, answer again)."""
        with self.lock:
            (self._silent.update if silent else self._silent.difference_update)(idents)

    def lose(self, count: int = 1) -> None:
        """The next ``count`` status packets are lost on the wire (noise): they never arrive."""
        with self.lock:
            self._lost = count

    def corrupt(self, count: int = 1) -> None:
        """The next ``count`` status packets have a wrong checksum or CRC."""
        with self.lock:
            self._corrupt = count

    def answer_as(self, ident: int, wrong_ident: int | None) -> None:
        """Servo ``ident`` puts ``wrong_ident`` in its status packets (None: its own again)."""
        with self.lock:
            if wrong_ident is None:
                self._aliases.pop(ident, None)
            else:
                self._aliases[ident] = wrong_ident

    def set_external_load(self, ident: int, load: float) -> None:
        """A load on the horn, as a signed fraction of the servo's maximum torque."""
        with self.lock:
            self._update()
            self.servos[ident].external_load = float(load)

    def move_by_hand(self, ident: int, degrees: float) -> None:
        """Turn a servo whose torque is off to an angle (180 is its centre)."""
        with self.lock:
            self._update()
            servo = self.servos[ident]
            if not servo.torque:
                servo.position = float(servo.table.role("PRESENT_POSITION").to_raw(degrees))
                servo.advance(0.0)

    def servo(self, ident: int) -> SimulatedServo:
        """The servo that now has id ``ident`` (ids can be changed through the bus)."""
        with self.lock:
            self._update()
            for servo in self.servos.values():
                if servo.ident == ident:
                    return servo
        raise KeyError(ident)

    # --- the bus ----------------------------------------------------------------------------
    def _update(self) -> None:
        now = time.perf_counter()
        dt = now - self._last_update
        self._last_update = now
        for servo in self.servos.values():
            servo.advance(dt)

    def _port_baud_rate(self) -> int | None:
        try:
            attributes = termios.tcgetattr(self._slave)
        except (termios.error, TypeError):
            return None
        return _SPEEDS.get(attributes[5])

    def received(self, data: bytes) -> None:
        arrived = time.perf_counter()
        for packet in self._reader.feed(data):
            with self.lock:
                self.packets += 1
                self._update()
                replies = self._answer(packet)
            self._transmit(packet, replies, arrived)

    def _transmit(self, packet: p.Packet, replies: list[bytes], arrived: float) -> None:
        if not self.line_time:
            for reply in replies:
                self.send(reply)
            return
        baud = self._port_baud_rate() or 1000000
        wire = (lambda n: n * 10.0 / baud)
        length = len(packet.params) + (10 if self.protocol == 2 else 6)
        # The wire time counts from the packet's arrival: the servos work while bytes travel.
        at = max(arrived, self._bus_free_at) + wire(length)
        for reply in replies:
            at += self._return_delay(reply) + wire(len(reply))
            sleep_until(at)
            self.send(reply)
        self._bus_free_at = at

    def _return_delay(self, reply: bytes) -> float:
        """The Return Delay Time (2 µs units) of the servo that sends ``reply``."""
        ident = reply[4] if self.protocol == 2 else reply[2]
        for servo in self.servos.values():
            if servo.ident == ident:
                return servo.memory[servo.table.field("Return Delay Time").address] * 2e-6
        return 0.0

    def _listening(self) -> list[SimulatedServo]:
        baud = self._port_baud_rate()
        return [s for s in self.servos.values()
                if s.ident not in self._silent and (baud is None or s.baud_rate == baud)]

    def _find(self, ident: int) -> SimulatedServo | None:
        for servo in self._listening():
            if servo.ident == ident:
                return servo
        return None

    def _status(self, servo: SimulatedServo, error: int, data: bytes = b"", instruction: int = -1,
                ident: int | None = None) -> bytes | None:
        """A status packet, unless the Status Return Level says to stay quiet."""
        level_field = servo.table.fields.get("Status Return Level")
        level = servo.memory[level_field.address] if level_field else 2
        if instruction != p.PING and (level == 0 or (level == 1 and instruction != p.READ)):
            return None
        ident = servo.ident if ident is None else ident
        ident = self._aliases.get(ident, ident)
        error |= servo.status_error()
        if self.protocol == 1:
            packet = p.packet1(ident, error, data)
        else:
            packet = p.packet2(ident, p.STATUS, bytes([error]) + data)
        if self._lost > 0:
            self._lost -= 1
            return None
        if self._corrupt > 0:
            self._corrupt -= 1
            packet = packet[:-1] + bytes([packet[-1] ^ 0x5A])
        return packet

    def _answer(self, packet: p.Packet) -> list[bytes]:
        params, ident, instruction = packet.params, packet.ident, packet.instruction
        if not packet.valid:
            servo = self._find(ident)
            if servo is None:
                return []
            reply = self._status(servo, p.P1_CHECKSUM if self.protocol == 1 else p.P2_CRC, b"", p.READ)
            return [reply] if reply else []
        two = self.protocol == 2
        word = (lambda at: params[at] | (params[at + 1] << 8)) if two else (lambda at: params[at])
        if instruction == p.PING:
            servos = self._listening() if ident == p.BROADCAST_ID and two else \
                [s for s in [self._find(ident)] if s]
            replies = []
            for servo in sorted(servos, key=lambda s: s.ident):
                data = bytes(servo.memory[0:2]) + bytes([servo.memory[servo.table.field("Firmware Version").address]]) \
                    if two else b""
                replies.append(self._status(servo, 0, data, p.PING))
            return replies
        if instruction in (p.SYNC_WRITE, p.BULK_WRITE):
            self._write_many(params, instruction)
            return []
        if instruction == p.SYNC_READ and two:
            address, length = word(0), word(2)
            replies = []
            for target in params[4:]:
                servo = self._find(target)
                if servo is None:
                    break               # the servos after a silent one wait for it in vain
                error, data = servo.read(address, length)
                replies.append(self._status(servo, error, data, p.READ))
            return [r for r in replies if r]
        if instruction == p.BULK_READ:
            return self._bulk_read(params)
        if instruction == p.ACTION:
            for servo in self._listening():
                if servo.registered:
                    servo.write(*servo.registered)
                    servo.registered = None
            return []
        servo = self._find(ident) if ident != p.BROADCAST_ID else None
        targets = self._listening() if ident == p.BROADCAST_ID else [servo] if servo else []
        if not targets:
            return []
        replies = []
        for servo in targets:
            if instruction == p.READ:
                error, data = servo.read(word(0), word(2) if two else params[1])
                replies.append(self._status(servo, error, data, p.READ))
            elif instruction in (p.WRITE, p.REG_WRITE):
                start, addressed = (2 if two else 1), servo.ident     # a new id answers as the old one
                if instruction == p.WRITE:
                    error = servo.write(word(0), params[start:])
                else:
                    servo.registered, error = (word(0), params[start:]), 0
                replies.append(self._status(servo, error, b"", instruction, addressed))
            elif instruction == p.REBOOT:
                servo.reboot()
                replies.append(self._status(servo, 0, b"", instruction))
            elif instruction == p.FACTORY_RESET:
                kept = servo.ident
                servo.memory = servo.table.initial_memory()
                servo._put("ID", kept)
                servo.position = float(servo.raw("PRESENT_POSITION"))
                replies.append(self._status(servo, 0, b"", instruction))
            else:
                replies.append(self._status(servo, p.P2_INSTRUCTION if two else p.P1_INSTRUCTION, b"", instruction))
        return [r for r in replies if r] if ident != p.BROADCAST_ID else []

    def _write_many(self, params: bytes, instruction: int) -> None:
        if instruction == p.SYNC_WRITE:         # address, length, then id + data per servo
            if self.protocol == 2:
                address, length, at = params[0] | params[1] << 8, params[2] | params[3] << 8, 4
            else:
                address, length, at = params[0], params[1], 2
            while at + 1 + length <= len(params):
                servo = self._find(params[at])
                if servo is not None:
                    servo.write(address, params[at + 1:at + 1 + length])
                at += 1 + length
        elif self.protocol == 2:                # bulk write: id, address, length, data per servo
            at = 0
            while at + 5 <= len(params):
                ident, address, length = params[at], params[at + 1] | params[at + 2] << 8, params[at + 3] | params[at + 4] << 8
                servo = self._find(ident)
                if servo is not None:
                    servo.write(address, params[at + 5:at + 5 + length])
                at += 5 + length

    def _bulk_read(self, params: bytes) -> list[bytes]:
        requests = []
        if self.protocol == 1:              # 00, then length, id, address per servo
            for at in range(1, len(params) - 2, 3):
                requests.append((params[at + 1], params[at + 2], params[at]))
        else:                               # id, address (2), length (2) per servo
            for at in range(0, len(params) - 4, 5):
                requests.append((params[at], params[at + 1] | params[at + 2] << 8, params[at + 3] | params[at + 4] << 8))
        replies = []
        for ident, address, length in requests:
            servo = self._find(ident)
            if servo is None:
                break
            error, data = servo.read(address, length)
            reply = self._status(servo, error, data, p.READ)
            if reply:
                replies.append(reply)
        return replies


def parse_ids(text: str) -> list[int]:
    """``"1-4,7"`` -> [1, 2, 3, 4, 7]."""
    ids: list[int] = []
    for part in str(text).replace(" ", "").split(","):
        if not part:
            continue
        first, dash, last = part.partition("-")
        try:
            ids.extend(range(int(first), int(last) + 1) if dash else [int(first)])
        except ValueError:
            raise ValueError(f"cannot read the servo ids '{text}' (write e.g. 1-4,7)") from None
    for ident in ids:
        if not 0 <= ident <= 252:
            raise ValueError(f"servo id {ident} is outside 0..252")
    return ids
