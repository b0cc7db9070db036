"""A virtual Dynamixel bus on a pseudo-terminal, answering Protocol 1.0 or 2.0 byte for byte.

Each simulated servo has the real control table of its model (``control_table``), answers
ping, read, write, reg write/action, sync write, sync read and bulk read/write (as its
protocol allows), and moves: its present position follows the goal position at the moving
speed (or the model's no-load speed), load rises with an external load and while moving,
temperature rises under load, and the overload, overheating and angle-limit errors are
raised as a real servo raises them (overload and overheating switch torque off); see
:mod:`ikaros.hardware.dynamixel.simulated_servo`. Every instruction packet received is kept
(``received_packets``, ``writes()``), so tests can check what a driver put on the bus.

A servo answers only while the driver's port runs at the servo's baud rate (read from the
terminal settings the driver made), so a wrong baud rate looks as it does on a real bus.
With ``line_time=True`` every packet takes the time it would take on the wire at that rate,
and each status packet comes after the servo's Return Delay Time.

Faults for tests: :meth:`silence` (a servo stops answering), :meth:`lose` (the next status
packets are lost), :meth:`corrupt` (the next status packets have a broken checksum or CRC), :meth:`answer_as` (a servo answers with a wrong id),
and ``disconnect()`` (the bus disappears); the world: :meth:`set_external_load`,
:meth:`set_temperature`, :meth:`move_by_hand`.
"""
from __future__ import annotations

import collections
import termios
import threading
import time

from ikaros.hardware.dynamixel import protocol as p
from ikaros.hardware.dynamixel.control_table import table_for_model
from ikaros.hardware.dynamixel.simulated_servo import SimulatedServo
from ikaros.hardware.pty_device import PtyDevice, sleep_until

DEFAULT_MODEL = {1: "AX-12A", 2: "XM430-W350"}
LOG_SIZE = 100000               # instruction packets kept in ``received_packets``

_SPEEDS = {getattr(termios, name): int(name[1:]) for name in dir(termios)
           if name.startswith("B") and name[1:].isdigit()}


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
        # every instruction packet received, in order, as (arrival time, packet): what the
        # driver put on the bus, for tests that check the bytes
        self.received_packets: collections.deque = collections.deque(maxlen=LOG_SIZE)

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

    def set_temperature(self, ident: int, celsius: float) -> None:
        """Servo ``ident`` and its surroundings are at ``celsius`` °C from now on (a servo under
        load warms further)."""
        with self.lock:
            self._update()
            self.servos[ident].set_temperature(celsius)

    def writes(self) -> list[tuple[int, int, bytes]]:
        """(id, address, data) of every value written so far (write, sync write, bulk write),
        in the order the packets came."""
        with self.lock:
            packets = [packet for _, packet in self.received_packets]
        return [write for packet in packets for write in p.writes_of(packet)]

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
                self.received_packets.append((arrived, packet))
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
            self._write_many(packet)
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
                servo.factory_reset()
                replies.append(self._status(servo, 0, b"", instruction))
            else:
                replies.append(self._status(servo, p.P2_INSTRUCTION if two else p.P1_INSTRUCTION, b"", instruction))
        return [r for r in replies if r] if ident != p.BROADCAST_ID else []

    def _write_many(self, packet: p.Packet) -> None:
        for ident, address, data in p.writes_of(packet):
            servo = self._find(ident)
            if servo is not None:
                servo.write(address, data)

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
