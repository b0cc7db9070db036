"""The MIDI messages of a Novation Launchpad X, from Novation's "Launchpad X Programmer's
reference manual": the System Exclusive header, the Programmer/Live mode switch and the LED
lighting message with RGB colours, and the pad numbers of the Programmer layout.

Messages are MIDI bytes (a System Exclusive message from F0 to F7); nothing here knows a
MIDI library, so the driver and the simulator share it.

The Programmer layout numbers the pads 10·row + column, row 1 at the bottom to 8 at the top
and column 1 at the left to 8 at the right (11 ... 88); the scene-launch buttons on the
right are column 9 (19 ... 89) and the top buttons row 9 (91 ... 98). Pads send Note On
(velocity 0 or Note Off on release), the buttons Control Change (value 127, then 0).
"""
from __future__ import annotations

SYSEX_START, SYSEX_END = 0xF0, 0xF7
HEADER = (0x00, 0x20, 0x29, 0x02, 0x0C)      # Novation's manufacturer id, Launchpad X
MODE_SWITCH = 0x0E                           # then 0: Live mode, 1: Programmer mode
LED_LIGHTING = 0x03                          # then colour specs
RGB = 0x03                                   # lighting type: red, green, blue 0..127
STATIC, FLASHING, PULSING = 0x00, 0x01, 0x02
LEVELS = 127                                 # the brightest level of a colour channel
GRID = 8                                     # pads per row and per column


def mode_switch(programmer: bool) -> bytes:
    """The System Exclusive message that selects Programmer mode (or Live mode)."""
    return bytes((SYSEX_START, *HEADER, MODE_SWITCH, int(programmer), SYSEX_END))


def led_lighting(colours: dict[int, tuple[int, int, int]]) -> bytes:
    """One LED lighting System Exclusive message that sets each LED (by its Programmer
    layout number) to an RGB colour, each channel 0..127."""
    body = []
    for index, (red, green, blue) in colours.items():
        body += [RGB, index, red, green, blue]
    return bytes((SYSEX_START, *HEADER, LED_LIGHTING, *body, SYSEX_END))


def pad_number(row_from_top: int, column: int) -> int:
    """The Programmer layout number of the pad ``row_from_top`` rows below the top row and
    ``column`` columns from the left (both from 0; column 8 is the scene-launch button)."""
    return 10 * (GRID - row_from_top) + column + 1


def pad_position(number: int) -> tuple[int, int] | None:
    """(row from the top, column from the left), both from 0, of a grid pad's number; None
    for a number that is not one of the 8 × 8 pads."""
    row, column = divmod(number, 10)
    if 1 <= row <= GRID and 1 <= column <= GRID:
        return GRID - row, column - 1
    return None


def parse_sysex(message: bytes) -> tuple[int, bytes] | None:
    """(command, data) of a Launchpad X System Exclusive message, or None for any other
    message."""
    if len(message) < len(HEADER) + 3 or message[0] != SYSEX_START or \
            message[-1] != SYSEX_END or tuple(message[1:1 + len(HEADER)]) != HEADER:
        return None
    return message[1 + len(HEADER)], bytes(message[2 + len(HEADER):-1])


def parse_colour_specs(data: bytes) -> list[tuple[int, int, tuple[int, ...]]]:
    """The (lighting type, LED, colour data) of each colour spec of an LED lighting message:
    static 1 byte (palette entry), flashing 2, pulsing 1, RGB 3. A ValueError for a spec
    that is cut short or of an unknown type."""
    sizes = {STATIC: 1, FLASHING: 2, PULSING: 1, RGB: 3}
    specs, at = [], 0
    while at < len(data):
        kind = data[at]
        if kind not in sizes or at + 2 + sizes[kind] > len(data):
            raise ValueError(f"bad colour spec at byte {at}: {data[at:].hex(' ')}")
        specs.append((kind, data[at + 1], tuple(data[at + 2:at + 2 + sizes[kind]])))
        at += 2 + sizes[kind]
    return specs
