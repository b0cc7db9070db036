"""A virtual SSC-32 on a pseudo-terminal, answering the commands of :mod:`ikaros.hardware.ssc32`.

Servos move linearly in time: a move with ``T`` takes that long (all servos of the command
arrive together), a channel with ``S`` moves at that many µs per second, and a move with
neither jumps at once. Faults: ``silent`` (stops answering queries) and ``corrupt`` (answers
with garbage bytes). ``commands`` keeps every command line received, for tests.
"""
from __future__ import annotations

import argparse
import re
import threading
import time

from ikaros.hardware.pty_device import PtyDevice
from ikaros.hardware.ssc32 import CHANNELS, PULSE_MAX, PULSE_MIN

HELP = "a Lynxmotion SSC-32 RC-servo controller (32 channels)"
VERSION = "SSC32-V2.50USB"
FAULTS = ("none", "silent", "corrupt")

_GROUP = re.compile(r"#(\d+)(?:P(\d+))?(?:S(\d+))?([LH])?")


class _Channel:
    def __init__(self):
        self.start = self.target = 0.0        # pulse widths, µs (0: off)
        self.t0 = self.t1 = 0.0               # start and end time of the move

    def pulse(self, now: float) -> float:
        if now >= self.t1 or self.start == 0 or self.target == 0:
            return self.target
        return self.start + (self.target - self.start) * (now - self.t0) / (self.t1 - self.t0)


class VirtualSSC32(PtyDevice):
    """The simulated board; ``pulse(channel)`` is a channel's present pulse width in µs."""

    name = "ssc32"

    def __init__(self, fault: str = "none", baudrate: int | None = None):
        super().__init__(baudrate)
        if fault not in FAULTS:
            raise ValueError(f"unknown fault '{fault}' (known: {', '.join(FAULTS)})")
        self.fault = fault
        self.commands: list[str] = []
        self.channels = [_Channel() for _ in range(CHANNELS)]
        self.discrete = [0] * CHANNELS
        self._pending = bytearray()
        self._lock = threading.Lock()

    def pulse(self, channel: int, now: float | None = None) -> float:
        with self._lock:
            return self.channels[channel].pulse(time.monotonic() if now is None else now)

    def received(self, data: bytes) -> None:
        self._pending += data
        while b"\r" in self._pending:
            line, _, rest = bytes(self._pending).partition(b"\r")
            self._pending = bytearray(rest)
            self._command(line.decode("ascii", "replace").strip().upper())

    def _command(self, line: str) -> None:
        if "\x1b" in line:                      # ESC cancels the command being typed
            line = line.rsplit("\x1b", 1)[1]
        if not line:
            return
        self.commands.append(line)
        if line.startswith("QP"):
            channels = [int(c) for c in re.findall(r"QP\s*(\d+)", line) if int(c) < CHANNELS]
            self._answer(bytes(int(round(self.pulse(c))) // 10 for c in channels))
        elif line == "Q":
            self._answer(b"+" if self._moving() else b".")
        elif line == "VER":
            self._answer(VERSION.encode("ascii") + b"\r")
        elif line.startswith("STOP"):
            for c in re.findall(r"\d+", line):
                self._stop_channel(int(c))
        elif line.startswith("#"):
            self._move(line)

    def _answer(self, reply: bytes) -> None:
        if self.fault == "silent":
            return
        if self.fault == "corrupt":
            reply = bytes(251 + b % 5 for b in reply)      # no valid reply byte is above 250
        self.send(reply)

    def _moving(self) -> bool:
        now = time.monotonic()
        with self._lock:
            return any(ch.t1 > now and ch.start != ch.target for ch in self.channels)

    def _stop_channel(self, channel: int) -> None:
        if channel < CHANNELS:
            now = time.monotonic()
            with self._lock:
                ch = self.channels[channel]
                ch.start = ch.target = ch.pulse(now)
                ch.t0 = ch.t1 = now

    def _move(self, line: str) -> None:
        body, _, time_text = line.partition("T")
        move_ms = int(time_text) if time_text.isdigit() else 0
        now = time.monotonic()
        moves = []
        for channel, pulse, speed, level in _GROUP.findall(body):
            channel = int(channel)
            if channel >= CHANNELS:
                continue
            if level:
                self.discrete[channel] = 1 if level == "H" else 0
            elif pulse:
                pulse = int(pulse)
                if pulse == 0 or PULSE_MIN <= pulse <= PULSE_MAX:
                    moves.append((channel, float(pulse), int(speed or 0)))
        with self._lock:
            durations = []
            for channel, pulse, speed in moves:
                ch = self.channels[channel]
                current = ch.pulse(now)
                distance = abs(pulse - current) if current and pulse else 0.0
                durations.append(distance / speed if speed else 0.0)
            duration = max(durations + [move_ms / 1000.0])
            for channel, pulse, _ in moves:
                ch = self.channels[channel]
                ch.start, ch.target = ch.pulse(now), pulse
                ch.t0, ch.t1 = now, now + duration


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--fault", choices=FAULTS, default="none",
                        help="inject a fault: silent (no answers), corrupt (garbled answers)")
    parser.add_argument("--baud", type=int, default=None,
                        help="simulate the transfer time of this baud rate (default: none)")


def start(options: argparse.Namespace) -> VirtualSSC32:
    return VirtualSSC32(fault=options.fault, baudrate=options.baud).start()
