"""ROS 2's CDR encoding (XCDR1, little-endian, the encapsulation header ``00 01 00 00``), as
rmw_cyclonedds and rosbag2 write it: each primitive aligned to its size from the start of
the payload, strings as a uint32 length (with the closing NUL) and their bytes, sequences as
a uint32 count and their elements. Arrays go in and out as NumPy arrays, in one copy."""
from __future__ import annotations

import struct

import numpy as np

HEADER = b"\x00\x01\x00\x00"          # CDR_LE, no options


class CdrError(ValueError):
    """Bytes that are not a message of the expected type."""


class Encoder:
    """Builds one message's bytes, header first."""

    def __init__(self):
        self._parts: list[bytes] = [HEADER]
        self._size = 0                  # bytes of payload so far (alignment is from here)

    def _align(self, n: int) -> None:
        pad = -self._size % n
        if pad:
            self._parts.append(b"\x00" * pad)
            self._size += pad

    def _put(self, data: bytes) -> None:
        self._parts.append(data)
        self._size += len(data)

    def primitive(self, fmt: str, value) -> None:
        """One value of struct format ``fmt`` (``i``, ``I``, ``f``, ``d``, ``B``)."""
        size = struct.calcsize(fmt)
        self._align(size)
        self._put(struct.pack("<" + fmt, value))

    def string(self, text: str) -> None:
        data = text.encode("utf-8") + b"\x00"
        self.primitive("I", len(data))
        self._put(data)

    def strings(self, texts) -> None:
        self.primitive("I", len(texts))
        for text in texts:
            self.string(text)

    def sequence(self, values, dtype: str) -> None:
        """A sequence of numbers of NumPy type ``dtype`` (``<f4``, ``<f8``, ``u1``)."""
        data = np.ascontiguousarray(values, dtype=dtype).reshape(-1)
        self.primitive("I", data.size)
        if data.size:
            self._align(data.itemsize)
            self._put(data.tobytes())

    def raw(self, data: bytes) -> None:
        """A uint8 sequence given as bytes."""
        self.primitive("I", len(data))
        self._put(bytes(data))

    def bytes(self) -> bytes:
        return b"".join(self._parts)


class Decoder:
    """Reads one message's bytes, in the order they were written."""

    def __init__(self, data: bytes):
        if len(data) < 4 or data[:2] != HEADER[:2]:
            raise CdrError(f"not little-endian CDR (header {bytes(data[:4]).hex() or 'empty'})")
        self._data = memoryview(data)[4:]
        self._at = 0

    def _take(self, n: int, align: int) -> memoryview:
        self._at += -self._at % align
        end = self._at + n
        if end > len(self._data):
            raise CdrError(f"the message ends after {len(self._data)} bytes; "
                           f"{end} were needed")
        part = self._data[self._at:end]
        self._at = end
        return part

    def primitive(self, fmt: str):
        size = struct.calcsize(fmt)
        return struct.unpack("<" + fmt, self._take(size, size))[0]

    def string(self) -> str:
        n = self.primitive("I")
        data = bytes(self._take(n, 1))
        return data[:-1].decode("utf-8", errors="replace") if n else ""

    def strings(self) -> list[str]:
        return [self.string() for _ in range(self.primitive("I"))]

    def sequence(self, dtype: str) -> np.ndarray:
        n = self.primitive("I")
        item = np.dtype(dtype).itemsize
        if n == 0:
            return np.zeros(0, dtype)
        return np.frombuffer(self._take(n * item, item), dtype=dtype)

    def raw(self) -> memoryview:
        return self._take(self.primitive("I"), 1)
