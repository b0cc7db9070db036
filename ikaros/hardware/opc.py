"""Open Pixel Control (OPC): LED pixels over TCP, as spoken to a FadeCandy server (fcserver).

A message is a 4-byte header and its data::

    channel (1 byte) | command (1 byte) | data length (2 bytes, big-endian) | data

Command 0 sets pixel colours: the data is one (red, green, blue) byte triple per pixel, from
the first pixel on. Channel 0 is every channel. Command 255 is system exclusive: its data
starts with a 2-byte system id (FadeCandy: 0x0001). The server does not answer; the default
TCP port is 7890.
"""
from __future__ import annotations

import socket
import struct

import numpy as np

from ikaros.hardware import DeviceError

DEFAULT_PORT = 7890
SET_PIXELS = 0
SYSTEM_EXCLUSIVE = 255
HEADER = struct.Struct(">BBH")
MAX_DATA = 65535


def message(channel: int, command: int, data: bytes) -> bytes:
    """One OPC message."""
    if not 0 <= channel <= 255 or not 0 <= command <= 255:
        raise ValueError(f"channel {channel} and command {command} must be in 0..255")
    if len(data) > MAX_DATA:
        raise ValueError(f"{len(data)} data bytes do not fit one message (at most {MAX_DATA})")
    return HEADER.pack(channel, command, len(data)) + bytes(data)


def pixel_message(channel: int, rgb) -> bytes:
    """The set-pixel-colours message for an (n, 3) array of colours in 0..1 (clipped; each
    rounded to the nearest of 0..255)."""
    values = np.clip(np.asarray(rgb, np.float64).reshape(-1, 3), 0.0, 1.0)
    return message(channel, SET_PIXELS, np.rint(values * 255).astype(np.uint8).tobytes())


def parse_messages(buffer: bytearray) -> list[tuple[int, int, bytes]]:
    """Take every complete message (channel, command, data) from the front of ``buffer``."""
    found = []
    while len(buffer) >= HEADER.size:
        channel, command, length = HEADER.unpack_from(buffer)
        if len(buffer) < HEADER.size + length:
            break
        found.append((channel, command, bytes(buffer[HEADER.size:HEADER.size + length])))
        del buffer[:HEADER.size + length]
    return found


def split_address(address: str) -> tuple[str, int]:
    """``host:port`` (or ``host``) as (host, port)."""
    host, _, port = address.strip().rpartition(":")
    if not host:
        return port or "127.0.0.1", DEFAULT_PORT
    try:
        return host, int(port)
    except ValueError:
        raise DeviceError(f"'{address}' is not host:port") from None


class OPCClient:
    """A connection to an OPC server."""

    def __init__(self, address: str, timeout: float = 1.0):
        self.address = address
        host, port = split_address(address)
        try:
            self.socket = socket.create_connection((host, port), timeout=timeout)
        except OSError as error:
            raise DeviceError(f"cannot connect to the OPC server at {host}:{port}: "
                              f"{error.strerror or error} (is fcserver running?)") from None
        self.socket.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)

    def send(self, data: bytes) -> None:
        try:
            self.socket.sendall(data)
        except TimeoutError:
            raise DeviceError(f"the OPC server at {self.address} does not take data (no "
                              f"progress within {self.socket.gettimeout()} s)") from None
        except OSError as error:
            raise DeviceError(f"the connection to the OPC server at {self.address} is lost: "
                              f"{error.strerror or error}") from None

    def set_pixels(self, channel: int, rgb) -> None:
        """Send the colours (an (n, 3) array in 0..1) of a channel's pixels."""
        self.send(pixel_message(channel, rgb))

    def close(self) -> None:
        try:
            self.socket.close()
        except OSError:
            pass
