"""The Lynxmotion SSC-32 RC-servo controller: its ASCII serial protocol and a driver.

Commands are ASCII lines ended by a carriage return::

    #0P1500T1000\\r           servo 0 to a pulse of 1500 µs, the move taking 1000 ms
    #0P1500#3P900S500\\r      servos 0 and 3 together; servo 3 at most 500 µs per second
    #0P0\\r                   no more pulses on servo 0 (an RC servo goes limp)
    QP 0 QP 3\\r              query pulse widths: one byte per servo, the width / 10
    Q\\r                      query movement: "." when all moves are done, "+" while moving
    VER\\r                    the firmware version, a line ended by a carriage return

Pulse widths are 500..2500 µs (0: off); the board starts without pulses until it is told a
position. The default baud rate is 115200 (jumpers: 2400, 9600, 38400, 115200).
"""
from __future__ import annotations

from typing import Iterable, Sequence

from ikaros.hardware import DeviceError
from ikaros.hardware.serial_port import SerialDevice

PULSE_MIN = 500
PULSE_MAX = 2500
CHANNELS = 32
DEFAULT_BAUD_RATE = 115200


def move_command(pulses: dict[int, int], time_ms: int | None = None,
                 speeds: dict[int, int] | None = None) -> bytes:
    """The group-move command that sets each channel's pulse width (µs; 0 turns it off),
    optionally with per-channel speeds (µs/s) and a time for the whole move (ms)."""
    if not pulses:
        raise ValueError("a move needs at least one channel")
    parts = []
    for channel, pulse in pulses.items():
        _check_channel(channel)
        pulse = int(pulse)
        if pulse != 0 and not PULSE_MIN <= pulse <= PULSE_MAX:
            raise ValueError(f"pulse width {pulse} µs on channel {channel} is outside "
                             f"{PULSE_MIN}..{PULSE_MAX} (or 0 for off)")
        part = f"#{channel}P{pulse}"
        speed = (speeds or {}).get(channel)
        if speed:
            part += f"S{int(speed)}"
        parts.append(part)
    if time_ms:
        if not 0 < time_ms <= 65535:
            raise ValueError(f"move time {time_ms} ms is outside 1..65535")
        parts.append(f"T{int(time_ms)}")
    return ("".join(parts) + "\r").encode("ascii")


def query_pulse_command(channels: Iterable[int]) -> bytes:
    """``QP a QP b ...\\r``: asks for the pulse widths of the channels, one byte each."""
    channels = list(channels)
    for channel in channels:
        _check_channel(channel)
    return (" ".join(f"QP {c}" for c in channels) + "\r").encode("ascii")


def decode_pulses(reply: bytes, count: int) -> list[int]:
    """Pulse widths (µs) from the reply to a QP query of ``count`` channels."""
    if len(reply) != count:
        raise ValueError(f"{len(reply)} of {count} bytes")
    bad = [b for b in reply if b != 0 and not PULSE_MIN // 10 <= b <= PULSE_MAX // 10]
    if bad:
        raise ValueError(f"pulse byte {bad[0]} is not a pulse width (50..250, or 0)")
    return [b * 10 for b in reply]


def _check_channel(channel: int) -> None:
    if not 0 <= channel < CHANNELS:
        raise ValueError(f"channel {channel} is outside 0..{CHANNELS - 1}")


class SSC32(SerialDevice):
    """An SSC-32 on a serial port (a real one, or a simulator's pseudo-terminal)."""

    what = "SSC-32"

    def __init__(self, device: str, baud_rate: int = DEFAULT_BAUD_RATE, timeout: float = 0.2):
        super().__init__(device, baud_rate, timeout)

    def move(self, pulses: dict[int, int], time_ms: int | None = None,
             speeds: dict[int, int] | None = None) -> None:
        """Start a group move (see :func:`move_command`)."""
        self._write(move_command(pulses, time_ms, speeds))

    def pulse_widths(self, channels: Sequence[int]) -> list[int]:
        """The present pulse widths (µs) of the channels (0: off)."""
        self.port.reset_input_buffer()
        self._write(query_pulse_command(channels))
        reply = self._read(len(channels), "pulse width query")
        try:
            return decode_pulses(reply, len(channels))
        except ValueError as error:
            raise DeviceError(f"the SSC-32 at '{self.device}' gave a corrupted reply to the "
                              f"pulse width query: {error}") from None

    def moving(self) -> bool:
        """True while a move is still in progress."""
        self.port.reset_input_buffer()
        self._write(b"Q\r")
        reply = self._read(1, "movement query")
        if reply not in (b".", b"+"):
            raise DeviceError(f"the SSC-32 at '{self.device}' gave a corrupted reply to the "
                              f"movement query: {reply!r}")
        return reply == b"+"

    def version(self) -> str:
        """The firmware version string."""
        self.port.reset_input_buffer()
        self._write(b"VER\r")
        try:
            reply = self.port.read_until(b"\r", 64)
        except Exception as error:
            raise DeviceError(f"the SSC-32 at '{self.device}' cannot be read: {error}") from None
        if not reply.endswith(b"\r"):
            raise DeviceError(f"the SSC-32 at '{self.device}' does not answer (version query)")
        return reply[:-1].decode("ascii", "replace")

    def off(self, channels: Iterable[int]) -> None:
        """The safe state: no pulses on the channels (RC servos go limp)."""
        channels = list(channels)
        if channels:
            self._write(move_command({c: 0 for c in channels}))
