"""The Bare Conductive Touch Board's DataStream output: text lines over USB serial.

The DataStream firmware writes, again and again, one line per kind of data, each a label
and one number per electrode (E0 to E11, and on some firmware a 13th for proximity)::

    TOUCH: 0 0 1 0 0 0 0 0 0 0 0 0 0
    TTHS: 40 40 ...       touch thresholds
    RTHS: 20 20 ...       release thresholds
    FDAT: 650 648 ...     filtered electrode data
    BVAL: 652 650 ...     baseline values
    DIFF: 2 2 ...         baseline minus filtered data
"""
from __future__ import annotations

LABELS = ("TOUCH", "TTHS", "RTHS", "FDAT", "BVAL", "DIFF")
BAUD_RATE = 57600


def parse_line(line: str) -> tuple[str, list[int]] | None:
    """(label, values) of one DataStream line, or None for anything else."""
    label, colon, rest = line.strip().partition(":")
    if not colon or label not in LABELS:
        return None
    try:
        return label, [int(v) for v in rest.split()]
    except ValueError:
        return None


def format_line(label: str, values) -> bytes:
    return f"{label}: {' '.join(str(int(v)) for v in values)}\r\n".encode()


class DataStreamReader:
    """Bytes in, complete (label, values) lines out."""

    def __init__(self):
        self.buffer = b""

    def feed(self, data: bytes) -> list[tuple[str, list[int]]]:
        self.buffer += data
        *lines, self.buffer = self.buffer.split(b"\n")
        found = []
        for line in lines:
            parsed = parse_line(line.decode("ascii", "replace"))
            if parsed is not None:
                found.append(parsed)
        return found
