"""The messages between the kernel and a script's worker process.

A message is a JSON header and the bytes of the arrays it carries, over a pipe::

    [4 bytes: header length][8 bytes: payload length][header JSON][payload]

The header is a dict with a ``kind`` and any fields; ``arrays`` lists ``[key, dtype,
shape]`` of the arrays whose C-order bytes follow, in order. Plain bytes and JSON (no
pickle) keep the two sides independent of each other's Python and NumPy versions.

This file is run by the worker too, from its file path: it needs only the standard
library and NumPy.
"""
from __future__ import annotations

import json
import struct

import numpy as np

_LENGTHS = struct.Struct("!IQ")


class WorkerGone(EOFError):
    """The other end closed the pipe (the worker process ended)."""


def send(stream, kind: str, fields: dict | None = None,
         arrays: dict[str, np.ndarray] | None = None) -> None:
    """Write one message to a binary stream and flush it."""
    header = dict(fields or {}, kind=kind)
    parts = []
    if arrays:
        described = []
        for key, array in arrays.items():
            array = np.asarray(array)
            if not array.flags.c_contiguous:
                array = array.copy(order="C")
            described.append([key, array.dtype.str, list(array.shape)])
            if array.nbytes:
                parts.append(memoryview(array.reshape(-1)).cast("B"))
        header["arrays"] = described
    text = json.dumps(header, separators=(",", ":")).encode()
    stream.write(_LENGTHS.pack(len(text), sum(p.nbytes for p in parts)) + text)
    for part in parts:
        stream.write(part)
    stream.flush()


def receive(stream) -> tuple[dict, dict]:
    """Read one message: (header, {key: array})."""
    header_length, _ = _LENGTHS.unpack(_read_exactly(stream, _LENGTHS.size))
    header = json.loads(_read_exactly(stream, header_length))
    arrays = {}
    for key, dtype, shape in header.pop("arrays", ()):
        target = np.empty(shape, dtype=np.dtype(dtype))
        if target.nbytes:
            _read_into(stream, memoryview(target.reshape(-1)).cast("B"))
        arrays[key] = target
    return header, arrays


def _read_exactly(stream, n: int) -> bytes:
    data = stream.read(n)
    if data is None or len(data) < n:
        raise WorkerGone("the pipe was closed")
    return data


def _read_into(stream, view) -> None:
    done = 0
    while done < len(view):
        got = stream.readinto(view[done:])
        if not got:
            raise WorkerGone("the pipe was closed")
        done += got
