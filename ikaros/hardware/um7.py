"""The CH Robotics / Redshift Labs UM7 orientation sensor's binary serial protocol (UM7
Datasheet, rev. 1.6): packets, registers and the values in them, and a driver that reads
the sensor in a background thread.

A packet is ``s`` ``n`` ``p``, a packet-type byte (bit 7 has data, bit 6 is batch, bits 5..2
the batch length in registers, bit 1 hidden, bit 0 command failed), an address, the data (0
bytes without data, 4 for one register, 4 × batch length for a batch) and a checksum: the
unsigned 16-bit sum of every byte before it, high byte first. Registers are 32 bits, most
significant byte first. A read is a packet without data (a batch read: the batch bit and
length set); the sensor answers with the data. A write has data; the sensor answers
COMMAND_COMPLETE: packet type 0 with the address. Command addresses (0xAA and up) run a
command when read.
"""
from __future__ import annotations

import struct
import threading
from dataclasses import dataclass

from ikaros.hardware import DeviceError
from ikaros.hardware.serial_port import SerialDevice

START = b"snp"
HAS_DATA, IS_BATCH, HIDDEN, COMMAND_FAILED = 0x80, 0x40, 0x02, 0x01
BAUD_RATE = 115200                       # the sensor's factory setting

# configuration registers: broadcast rates (Hz, one byte each)
CREG_COM_RATES3 = 0x03                   # processed accel (31:24), gyro (23:16), mag (15:8)
CREG_COM_RATES4 = 0x04                   # all processed data (7:0): batch of 12 from 0x61
CREG_COM_RATES5 = 0x05                   # quaternion (31:24), Euler (23:16), position, velocity
# data registers
DREG_GYRO_PROC_X = 0x61                  # x, y, z (degrees/s, float), time: 0x61..0x64
DREG_ACCEL_PROC_X = 0x65                 # x, y, z (float), time: 0x65..0x68
DREG_MAG_PROC_X = 0x69                   # x, y, z, time: 0x69..0x6C
DREG_EULER_PHI_THETA = 0x70              # roll (31:16) and pitch (15:0), int16 / 91.02222
DREG_EULER_PSI = 0x71                    # yaw (31:16)
DREG_EULER_PHI_THETA_DOT = 0x72          # roll and pitch rates, int16 / 16
DREG_EULER_PSI_DOT = 0x73                # yaw rate (31:16)
DREG_EULER_TIME = 0x74                   # float
GET_FW_REVISION = 0xAA                   # the first command address
ANGLE_SCALE = 91.02222                   # int16 counts per degree
RATE_SCALE = 16.0                        # int16 counts per degree per second


def checksum(data: bytes) -> int:
    return sum(data) & 0xFFFF


def packet(address: int, data: bytes = b"", batch: bool | None = None,
           packet_type: int | None = None) -> bytes:
    """A packet with ``data`` (whole registers) at ``address``; more than one register is
    a batch. ``packet_type`` overrides the type byte (a batch read, COMMAND_COMPLETE)."""
    if packet_type is None:
        registers = len(data) // 4
        batch = registers > 1 if batch is None else batch
        packet_type = (HAS_DATA if data else 0) | \
            (IS_BATCH | (registers & 0x0F) << 2 if batch else 0)
    body = START + bytes((packet_type, address)) + data
    return body + struct.pack(">H", checksum(body))


def read_request(address: int, count: int = 1) -> bytes:
    """A packet that asks for ``count`` registers from ``address`` (a batch read when more
    than one)."""
    if not 1 <= count <= 15:
        raise ValueError("a UM7 batch holds 1 to 15 registers")
    return packet(address, packet_type=(IS_BATCH | count << 2) if count > 1 else 0)


@dataclass
class Packet:
    packet_type: int
    address: int
    data: bytes

    @property
    def has_data(self) -> bool:
        return bool(self.packet_type & HAS_DATA)

    @property
    def failed(self) -> bool:
        return bool(self.packet_type & COMMAND_FAILED)

    def registers(self) -> dict[int, bytes]:
        """The registers in the data, by address."""
        return {self.address + k: self.data[4 * k:4 * k + 4] for k in range(len(self.data) // 4)}


def data_length(packet_type: int) -> int:
    if not packet_type & HAS_DATA:
        return 0
    if packet_type & IS_BATCH:
        return 4 * ((packet_type >> 2) & 0x0F)
    return 4


class PacketParser:
    """Packets out of a byte stream that comes in pieces. Bytes before a start, and packets
    whose checksum is wrong, are skipped (``bad`` counts the latter)."""

    def __init__(self):
        self.buffer = bytearray()
        self.bad = 0

    def feed(self, chunk: bytes) -> list[Packet]:
        self.buffer += chunk
        found = []
        while True:
            start = self.buffer.find(START)
            if start < 0:
                del self.buffer[:max(0, len(self.buffer) - 2)]
                return found
            del self.buffer[:start]
            if len(self.buffer) < 5:
                return found
            length = data_length(self.buffer[3])
            end = 5 + length + 2
            if len(self.buffer) < end:
                return found
            body, (sent,) = bytes(self.buffer[:end - 2]), struct.unpack(
                ">H", self.buffer[end - 2:end])
            if checksum(body) != sent:
                self.bad += 1
                del self.buffer[:1]
                continue
            found.append(Packet(body[3], body[4], body[5:]))
            del self.buffer[:end]


def float_register(data: bytes) -> float:
    return struct.unpack(">f", data)[0]


def high_low(data: bytes) -> tuple[int, int]:
    """The two signed 16-bit halves of a register (bits 31:16, bits 15:0)."""
    return struct.unpack(">hh", data)


class UM7(SerialDevice):
    """A UM7 on a serial port. A background thread reads every packet the sensor sends
    (answers and broadcasts) and keeps the newest value of each register; ``request``
    asks for registers without waiting for the answer."""

    what = "UM7"

    def __init__(self, device: str, baud_rate: int = BAUD_RATE, timeout: float = 0.05):
        super().__init__(device, baud_rate, timeout)
        self.parser = PacketParser()
        self.registers: dict[int, bytes] = {}
        self.received = 0                  # packets received
        self.failures: list[int] = []     # addresses of commands the sensor said failed
        self.error: str | None = None     # why reading stopped
        self._lock = threading.Lock()
        self._stopping = threading.Event()
        self._thread = threading.Thread(target=self._read, name=f"um7-{device}", daemon=True)
        self._thread.start()

    def _read(self) -> None:
        while not self._stopping.is_set():
            try:
                chunk = self.port.read(max(1, self.port.in_waiting))
            except Exception as e:           # pyserial's errors: the port went away
                if not self._stopping.is_set():
                    self.error = f"the UM7 at '{self.device}' cannot be read: {e}"
                return
            for p in self.parser.feed(chunk):
                with self._lock:
                    self.received += 1
                    if p.failed:
                        self.failures.append(p.address)
                    self.registers.update(p.registers())

    def request(self, address: int, count: int = 1) -> None:
        """Ask for ``count`` registers from ``address``; the answer arrives in
        ``registers``."""
        if self.error:
            raise DeviceError(self.error)
        self._write(read_request(address, count))

    def register(self, address: int) -> bytes | None:
        with self._lock:
            return self.registers.get(address)

    def close(self) -> None:
        self._stopping.set()
        self._thread.join(timeout=1.0)
        super().close()
