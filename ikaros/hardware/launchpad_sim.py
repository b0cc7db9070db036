"""A simulated Novation Launchpad X in this process, with the two MIDI ports of the real one
(:mod:`ikaros.hardware.midi`: a port named ``sim:launchpad``).

It answers what Novation's Launchpad X Programmer's reference manual gives for Programmer
mode: the Programmer/Live mode switch, the LED lighting System Exclusive message (static,
flashing, pulsing and RGB colour specs) and Note On / Control Change messages on channel 1
that light a pad or button with a palette colour. ``press(row, column)`` sends what the
device sends when a pad is pressed: Note On with the pad's Programmer-layout number (a
Control Change for the scene-launch column and the top row), and ``release`` the Note Off.
Not modelled: the Live-mode layouts (Session, Note, Custom: presses are always sent with
Programmer-layout numbers), the colour palette's RGB values (a palette colour is kept as its
number), flashing and pulsing in time, aftertouch, the DAW port, text scrolling, sleep and
the other configuration messages, which are kept in ``messages`` and otherwise ignored.
"""
from __future__ import annotations

import threading

from ikaros.hardware import launchpad
from ikaros.hardware.midi import SimulatedDevice

NOTE_ON, NOTE_OFF, CONTROL_CHANGE = 0x90, 0x80, 0xB0


class SimulatedLaunchpad(SimulatedDevice):
    """The simulated Launchpad X. ``mode`` is "live" or "programmer"; ``leds`` maps an LED's
    Programmer-layout number to its colour: ("rgb", r, g, b) with 0..127 channels, or
    ("palette", n), ("flashing", a, b), ("pulsing", n); ``messages`` keeps every message
    received."""

    name = "Simulated Launchpad X LPX"

    def __init__(self):
        super().__init__()
        self.mode = "live"
        self.leds: dict[int, tuple] = {}
        self.messages: list[bytes] = []
        self.state_lock = threading.Lock()

    def received(self, message: bytes) -> None:
        with self.state_lock:
            self.messages.append(bytes(message))
            parsed = launchpad.parse_sysex(message)
            if parsed is not None:
                self._sysex(*parsed)
            elif len(message) == 3 and message[0] in (NOTE_ON, CONTROL_CHANGE):
                self._light(message[1], ("palette", message[2]))
            elif len(message) == 3 and message[0] == NOTE_OFF:
                self._light(message[1], ("palette", 0))

    def _sysex(self, command: int, data: bytes) -> None:
        if command == launchpad.MODE_SWITCH and len(data) == 1:
            self.mode = "programmer" if data[0] else "live"
        elif command == launchpad.LED_LIGHTING:
            try:
                specs = launchpad.parse_colour_specs(data)
            except ValueError:
                return                          # the real device ignores a bad message
            names = {launchpad.STATIC: "palette", launchpad.FLASHING: "flashing",
                     launchpad.PULSING: "pulsing", launchpad.RGB: "rgb"}
            for kind, led, colour in specs:
                self._light(led, (names[kind], *colour))

    def _light(self, led: int, colour: tuple) -> None:
        if colour in (("palette", 0), ("rgb", 0, 0, 0)):
            self.leds.pop(led, None)
        else:
            self.leds[led] = colour

    def colour(self, row_from_top: int, column: int) -> tuple:
        """The colour of a pad (row and column from 0 at the top left); ("rgb", 0, 0, 0)
        when it is dark."""
        with self.state_lock:
            return self.leds.get(launchpad.pad_number(row_from_top, column), ("rgb", 0, 0, 0))

    def press(self, row_from_top: int, column: int, velocity: int = 127) -> None:
        """A press of the pad (or button, column 8; row -1 is the top row of buttons)."""
        self.send_to_host(self._event(row_from_top, column, velocity))

    def release(self, row_from_top: int, column: int) -> None:
        number = launchpad.pad_number(row_from_top, column)
        if self._is_button(number):
            self.send_to_host(bytes((CONTROL_CHANGE, number, 0)))
        else:
            self.send_to_host(bytes((NOTE_OFF, number, 0)))

    def _event(self, row_from_top: int, column: int, velocity: int) -> bytes:
        number = launchpad.pad_number(row_from_top, column)
        if self._is_button(number):
            return bytes((CONTROL_CHANGE, number, 127))
        return bytes((NOTE_ON, number, max(1, min(127, velocity))))

    @staticmethod
    def _is_button(number: int) -> bool:
        return number % 10 == 9 or number >= 90


def start() -> SimulatedLaunchpad:
    return SimulatedLaunchpad()
