"""Binary data frames of the web UI protocol, and image compression.

A frame is: 4 bytes little-endian header length N, N bytes of UTF-8 JSON header, then the
payloads. The header is ``{"tick", "time", "buffers": [{"path", "format", "shape",
"offset", "length"}]}``; offsets and lengths count bytes from the end of the header. ``raw``
payloads are little-endian float32 in row-major order; ``png`` and ``jpeg`` payloads are
image files made from arrays of values 0..1, (rows, cols) gray or (3, rows, cols) colour.
"""
from __future__ import annotations

import io
import json
import struct

import numpy as np

FORMATS = ("raw", "png", "jpeg", "history", "events")
RAW_FORMATS = ("raw", "history", "events")      # float32 payloads
IMAGE_FORMATS = ("png", "jpeg")
JPEG_QUALITY = 85
PNG_COMPRESS_LEVEL = 1      # fast: the data are live, not archived


def image_shape_ok(shape: tuple) -> bool:
    """Whether an array of this shape can be sent as a png/jpeg image."""
    return (len(shape) == 2 and min(shape) > 0) or \
        (len(shape) == 3 and shape[0] == 3 and min(shape) > 0)


def raw_bytes(array: np.ndarray) -> bytes:
    """Little-endian float32, row-major."""
    return np.ascontiguousarray(array, dtype="<f4").tobytes()


def image_bytes(array: np.ndarray, fmt: str, quality: int = JPEG_QUALITY) -> bytes:
    """A PNG or JPEG file (of this quality, 1-100) of an array of values 0..1: (rows, cols)
    gray or (3, rows, cols) colour."""
    from PIL import Image
    a = np.nan_to_num(np.asarray(array, dtype=np.float32), nan=0.0, posinf=1.0, neginf=0.0)
    pixels = (np.clip(a, 0.0, 1.0) * 255.0 + 0.5).astype(np.uint8)
    if pixels.ndim == 3:
        image = Image.fromarray(np.ascontiguousarray(pixels.transpose(1, 2, 0)), "RGB")
    elif pixels.ndim == 2:
        image = Image.fromarray(pixels, "L")
    else:
        raise ValueError(f"an image must be (rows, cols) or (3, rows, cols), not "
                         f"{tuple(a.shape)}")
    out = io.BytesIO()
    if fmt == "png":
        image.save(out, "PNG", compress_level=PNG_COMPRESS_LEVEL)
    elif fmt == "jpeg":
        image.save(out, "JPEG", quality=quality)
    else:
        raise ValueError(f'unknown image format "{fmt}"')
    return out.getvalue()


def encode_array(array: np.ndarray, fmt: str, quality: int = JPEG_QUALITY) -> bytes:
    """The payload of one buffer in one format (``quality``: of a JPEG image)."""
    if fmt == "raw":
        return raw_bytes(array)
    return image_bytes(array, fmt, quality)


def encode_frame(tick: int, time: float, items: list[tuple]) -> bytes:
    """A binary data frame from (path, format, shape, payload) items; an item may have a
    fifth element, a dict of more header fields for its buffer (history formats)."""
    buffers, offset = [], 0
    for path, fmt, shape, payload, *more in items:
        buffers.append({"path": path, "format": fmt, "shape": list(shape), "offset": offset,
                        "length": len(payload), **(more[0] if more else {})})
        offset += len(payload)
    header = json.dumps({"tick": int(tick), "time": float(time), "buffers": buffers},
                        separators=(",", ":")).encode("utf-8")
    return b"".join([struct.pack("<I", len(header)), header] + [it[3] for it in items])


def decode_frame(frame: bytes) -> tuple[dict, dict]:
    """(header, {path: array or image bytes}) of a data frame: raw payloads come back as
    float32 arrays of their shape, png/jpeg payloads as the file bytes."""
    (n,) = struct.unpack_from("<I", frame, 0)
    header = json.loads(frame[4:4 + n].decode("utf-8"))
    body = memoryview(frame)[4 + n:]
    out = {}
    for b in header["buffers"]:
        payload = body[b["offset"]:b["offset"] + b["length"]]
        if b["format"] in RAW_FORMATS:
            out[b["path"]] = np.frombuffer(payload, dtype="<f4").reshape(b["shape"]).copy()
        else:
            out[b["path"]] = bytes(payload)
    return header, out
