"""Link messages: a header (JSON) and whole arrays (raw bytes), signed with a shared key.

A message is a list of ZeroMQ frames::

    [signature, header, array 0, array 1, ...]

``header`` is UTF-8 JSON holding at least ``tick`` and ``time`` (the sender's wall-clock
time stamp, seconds since the epoch), and ``arrays``: the dtype and shape of each array
frame. ``signature`` is HMAC-SHA256 over the header and every array frame with the shared
key, or empty when the link has no key (allowed on 127.0.0.1 only). Nothing is ever
unpickled: a message from a peer can carry data, never code.
"""
from __future__ import annotations

import hashlib
import hmac
import json
import time

import numpy as np


class LinkError(Exception):
    """A link could not be made or used (bad address, missing key, refused peer)."""


class WrongKey(LinkError):
    """A message whose signature does not match the key: the peer uses another key."""


class BadMessage(LinkError):
    """A message that is not a link message (wrong frames, header or sizes)."""


def _signature(key: bytes, frames) -> bytes:
    mac = hmac.new(key, digestmod=hashlib.sha256)
    for frame in frames:
        mac.update(len(frame).to_bytes(8, "little"))
        mac.update(frame)
    return mac.digest()


def encode(header: dict, arrays=(), key: bytes | None = None) -> list:
    """The frames of one message; ``header`` gets ``time`` (now) unless it has one."""
    arrays = [np.asarray(a) for a in arrays]
    header = dict(header)
    header.setdefault("time", time.time())
    header["arrays"] = [[a.dtype.str, list(a.shape)] for a in arrays]
    frames = [json.dumps(header, separators=(",", ":")).encode()]
    frames.extend(memoryview(a.reshape(-1).view(np.uint8)) for a in arrays)
    return [_signature(key, frames) if key else b""] + frames


def decode(frames: list, key: bytes | None = None) -> tuple[dict, list]:
    """(header, arrays) of a message; raises WrongKey or BadMessage. The arrays are
    read-only views of the received frames."""
    if len(frames) < 2:
        raise BadMessage(f"a link message has at least 2 frames, not {len(frames)}")
    signature, body = bytes(frames[0]), frames[1:]
    if key:
        if not signature:
            raise WrongKey("the peer sends unsigned messages but this link has a key")
        if not hmac.compare_digest(signature, _signature(key, [bytes(f) for f in body])):
            raise WrongKey("a message's signature does not match this link's key "
                           "(the peer uses another key)")
    elif signature:
        raise WrongKey("the peer signs its messages with a key but this link has none")
    try:
        header = json.loads(bytes(body[0]))
        specs = header["arrays"]
        if len(specs) != len(body) - 1:
            raise ValueError(f"{len(specs)} arrays announced, {len(body) - 1} sent")
        arrays = []
        for (dtype, shape), frame in zip(specs, body[1:]):
            dt = np.dtype(dtype)
            if dt.hasobject:
                raise ValueError("object arrays are not allowed")
            arrays.append(np.frombuffer(frame, dtype=dt).reshape(shape))
        return header, arrays
    except (ValueError, KeyError, TypeError) as e:
        raise BadMessage(f"not a link message: {e}") from None
