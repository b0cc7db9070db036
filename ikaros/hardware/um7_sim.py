"""A virtual UM7 orientation sensor on a pseudo-terminal, speaking the binary packets of
:mod:`ikaros.hardware.um7` (UM7 Datasheet rev. 1.6) byte for byte.

It answers reads of any register (one or a batch), takes writes (answering
COMMAND_COMPLETE), answers GET_FW_REVISION with its firmware string and the other commands
with COMMAND_COMPLETE, and broadcasts at the rates of CREG_COM_RATES3, 4 and 5: processed
gyro and accelerometer data, all processed data (a batch of 12 from 0x61), Euler angles (a
batch of 5 from 0x70). Its attitude is what ``set_attitude`` gives, turning at
``yaw_rate`` degrees a second; the processed gyro reads the Euler rates (roll, pitch and
yaw rate, degrees/s) and the accelerometer the gravity seen by a sensor at that roll and
pitch, in m/s² (x forward, y right, z down: (0, 0, −9.80665) when level). Not modelled:
the Kalman filter, the magnetometer (its registers read 0), GPS, the NMEA packets, the
hidden registers, flash and baud-rate settings. Faults: ``silent`` (no answers) and
``corrupt`` (every packet's checksum is wrong).
"""
from __future__ import annotations

import argparse
import math
import struct
import threading
import time

from ikaros.hardware import um7
from ikaros.hardware.pty_device import PtyDevice

HELP = "a Redshift Labs UM7 orientation sensor (binary packets, 115200 baud)"
FIRMWARE = b"U7SM"                   # the simulator's answer to GET_FW_REVISION
FAULTS = ("none", "silent", "corrupt")
GRAVITY = 9.80665


class VirtualUM7(PtyDevice):
    """The simulated sensor. ``requests`` keeps every packet received, for tests."""

    name = "um7"

    def __init__(self, roll: float = 0.0, pitch: float = 0.0, yaw: float = 0.0,
                 yaw_rate: float = 0.0, rate: int = 0, fault: str = "none",
                 baudrate: int | None = None):
        super().__init__(baudrate)
        if fault not in FAULTS:
            raise ValueError(f"unknown fault '{fault}' (known: {', '.join(FAULTS)})")
        self.fault = fault
        self.parser = um7.PacketParser()
        self.requests: list[um7.Packet] = []
        self.config = {um7.CREG_COM_RATES3: 0, um7.CREG_COM_RATES4: rate & 0xFF,
                       um7.CREG_COM_RATES5: (rate & 0xFF) << 16}
        self._lock = threading.Lock()
        self._start = time.monotonic()
        self.set_attitude(roll, pitch, yaw, yaw_rate)
        self._broadcaster = threading.Thread(target=self._broadcast, name="um7-sim-broadcast",
                                             daemon=True)

    def start(self) -> "VirtualUM7":
        super().start()
        if not self._broadcaster.is_alive():
            self._broadcaster.start()
        return self

    def set_attitude(self, roll: float, pitch: float, yaw: float, yaw_rate: float = 0.0):
        """The attitude (degrees) now, and how fast the yaw turns (degrees/s)."""
        with self._lock:
            self._attitude = (roll, pitch, yaw)
            self._yaw_rate = yaw_rate
            self._since = time.monotonic()

    def attitude(self) -> tuple[float, float, float]:
        """Roll, pitch and yaw (degrees, yaw in -180..180) now."""
        with self._lock:
            roll, pitch, yaw = self._attitude
            yaw += self._yaw_rate * (time.monotonic() - self._since)
        return roll, pitch, (yaw + 180.0) % 360.0 - 180.0

    # --- registers --------------------------------------------------------------------------

    def register(self, address: int) -> bytes:
        """A register's 4 bytes as the sensor holds them now."""
        if address in self.config:
            return struct.pack(">I", self.config[address])
        roll, pitch, yaw = self.attitude()
        now = time.monotonic() - self._start
        gyro = (0.0, 0.0, self._yaw_rate)
        r, p = math.radians(roll), math.radians(pitch)
        accel = (GRAVITY * math.sin(p), -GRAVITY * math.sin(r) * math.cos(p),
                 -GRAVITY * math.cos(r) * math.cos(p))
        floats = {um7.DREG_GYRO_PROC_X: gyro[0], um7.DREG_GYRO_PROC_X + 1: gyro[1],
                  um7.DREG_GYRO_PROC_X + 2: gyro[2], um7.DREG_GYRO_PROC_X + 3: now,
                  um7.DREG_ACCEL_PROC_X: accel[0], um7.DREG_ACCEL_PROC_X + 1: accel[1],
                  um7.DREG_ACCEL_PROC_X + 2: accel[2], um7.DREG_ACCEL_PROC_X + 3: now,
                  um7.DREG_MAG_PROC_X + 3: now, um7.DREG_EULER_TIME: now}
        if address in floats:
            return struct.pack(">f", floats[address])
        if address == um7.DREG_EULER_PHI_THETA:
            return struct.pack(">hh", _counts(roll, um7.ANGLE_SCALE),
                               _counts(pitch, um7.ANGLE_SCALE))
        if address == um7.DREG_EULER_PSI:
            return struct.pack(">hh", _counts(yaw, um7.ANGLE_SCALE), 0)
        if address == um7.DREG_EULER_PHI_THETA_DOT:
            return struct.pack(">hh", 0, 0)
        if address == um7.DREG_EULER_PSI_DOT:
            return struct.pack(">hh", _counts(self._yaw_rate, um7.RATE_SCALE), 0)
        return bytes(4)

    def _registers(self, address: int, count: int) -> bytes:
        return b"".join(self.register(address + k) for k in range(count))

    # --- talking ----------------------------------------------------------------------------

    def received(self, data: bytes) -> None:
        for request in self.parser.feed(data):
            self.requests.append(request)
            self._answer(request)

    def _answer(self, request: um7.Packet) -> None:
        address = request.address
        if request.has_data:                              # a write
            for register, value in request.registers().items():
                if register in self.config:
                    self.config[register] = struct.unpack(">I", value)[0]
            self._send(um7.packet(address, packet_type=0))
        elif address == um7.GET_FW_REVISION:
            self._send(um7.packet(address, FIRMWARE, batch=False))
        elif address > um7.GET_FW_REVISION:               # another command: done at once
            self._send(um7.packet(address, packet_type=0))
        else:                                             # a read: the same batch bits
            batch = bool(request.packet_type & um7.IS_BATCH)
            count = (request.packet_type >> 2) & 0x0F if batch else 1
            self._send(um7.packet(address, self._registers(address, count), batch=batch))

    def _send(self, message: bytes) -> None:
        if self.fault == "silent":
            return
        if self.fault == "corrupt":
            message = message[:-1] + bytes([message[-1] ^ 0xFF])
        self.send(message)

    def _broadcast(self) -> None:
        due: dict[str, float] = {}
        while not self._stopping.is_set():
            now = time.monotonic()
            rates3, rates4 = self.config[um7.CREG_COM_RATES3], self.config[um7.CREG_COM_RATES4]
            streams = {"all": ((rates4 & 0xFF), um7.DREG_GYRO_PROC_X, 12),
                       "accel": ((rates3 >> 24) & 0xFF if not rates4 & 0xFF else 0,
                                 um7.DREG_ACCEL_PROC_X, 4),
                       "gyro": ((rates3 >> 16) & 0xFF if not rates4 & 0xFF else 0,
                                um7.DREG_GYRO_PROC_X, 4),
                       "euler": ((self.config[um7.CREG_COM_RATES5] >> 16) & 0xFF,
                                 um7.DREG_EULER_PHI_THETA, 5)}
            for name, (hz, address, count) in streams.items():
                if hz and now >= due.get(name, 0.0):
                    due[name] = now + 1.0 / hz
                    self._send(um7.packet(address, self._registers(address, count)))
            self._stopping.wait(0.002)


def _counts(value: float, scale: float) -> int:
    return max(-32768, min(32767, round(value * scale)))


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--roll", type=float, default=0.0, help="roll in degrees")
    parser.add_argument("--pitch", type=float, default=0.0, help="pitch in degrees")
    parser.add_argument("--yaw", type=float, default=0.0, help="yaw in degrees at the start")
    parser.add_argument("--yaw-rate", type=float, default=0.0,
                        help="how fast the yaw turns, degrees a second")
    parser.add_argument("--rate", type=int, default=0,
                        help="broadcast all processed data and the Euler angles this many "
                             "times a second (0: answer reads only)")
    parser.add_argument("--fault", choices=FAULTS, default="none",
                        help="inject a fault: silent (no answers), corrupt (bad checksums)")
    parser.add_argument("--baud", type=int, default=None,
                        help="simulate the transfer time of this baud rate (default: none)")


def start(options: argparse.Namespace) -> VirtualUM7:
    return VirtualUM7(options.roll, options.pitch, options.yaw, options.yaw_rate,
                      options.rate, options.fault, options.baud).start()
