"""Binary data frames of the web UI protocol, and image compression.

A frame is: 4 bytes little-endian header length N, N bytes of UTF-8 JSON header, then the
payloads. The header is ``{"tick", "time", "buffers": [{"path", "format", "shape",
"offset", "length"}]}``; offsets and lengths count bytes from the end of the header. ``raw``
payloads are little-endian float32 in row-major order; ``png`` and ``jpeg`` payloads are
image files made from arrays of values 0..1, (rows, cols) gray or (3, rows, cols) colour.
"""
from __future__ import annotations

import functools
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


def image_pixels(array: np.ndarray) -> np.ndarray:
    """The 8-bit pixels of an array of values 0..1, in its layout ((rows, cols) gray or
    (3, rows, cols) colour): each value clipped to 0..1 and rounded (halves up) to 0..255;
    NaN is 0."""
    a = np.asarray(array, dtype=np.float32)
    if not image_shape_ok(a.shape):
        raise ValueError(f"an image must be (rows, cols) or (3, rows, cols), not "
                         f"{tuple(a.shape)}")
    with np.errstate(over="ignore", invalid="ignore"):
        levels = np.multiply(a, np.float32(255.0), dtype=np.float32)
        np.clip(levels, 0.0, 255.0, out=levels)
    levels[np.isnan(levels)] = 0.0
    levels += np.float32(0.5)
    return levels.astype(np.uint8)


def _opencv_file(pixels: np.ndarray, fmt: str, quality: int) -> bytes:
    cv2 = _opencv()
    if pixels.ndim == 3:
        pixels = cv2.merge((pixels[2], pixels[1], pixels[0]))     # OpenCV's order: BGR
    flags = [cv2.IMWRITE_PNG_COMPRESSION, PNG_COMPRESS_LEVEL] if fmt == "png" else \
        [cv2.IMWRITE_JPEG_QUALITY, quality]
    ok, file = cv2.imencode(f".{fmt}", pixels, flags)
    if not ok:
        raise ValueError(f"OpenCV could not encode a {fmt} image of {pixels.shape}")
    return file.tobytes()


def _pillow_file(pixels: np.ndarray, fmt: str, quality: int) -> bytes:
    from PIL import Image
    if pixels.ndim == 3:
        image = Image.fromarray(np.ascontiguousarray(pixels.transpose(1, 2, 0)), "RGB")
    else:
        image = Image.fromarray(pixels, "L")
    out = io.BytesIO()
    if fmt == "png":
        image.save(out, "PNG", compress_level=PNG_COMPRESS_LEVEL)
    else:
        image.save(out, "JPEG", quality=quality)
    return out.getvalue()


ENCODERS = {"opencv": _opencv_file, "pillow": _pillow_file}


@functools.cache
def _opencv():
    """OpenCV when it is installed, else None."""
    try:
        import cv2
    except ImportError:
        return None
    return cv2


def image_encoder() -> str:
    """The encoder of the web UI's images: OpenCV when it is installed (its encoders let
    Python's other threads run while they work, so a real-time tick never waits for an
    image), else Pillow."""
    return "opencv" if _opencv() is not None else "pillow"


def image_bytes(array: np.ndarray, fmt: str, quality: int = JPEG_QUALITY,
                encoder: str | None = None) -> bytes:
    """A PNG or JPEG file (of this quality, 1-100) of an array of values 0..1: (rows, cols)
    gray or (3, rows, cols) colour; ``encoder``: ``opencv`` or ``pillow`` (default:
    :func:`image_encoder`)."""
    if fmt not in IMAGE_FORMATS:
        raise ValueError(f'unknown image format "{fmt}"')
    return ENCODERS[encoder or image_encoder()](image_pixels(array), fmt, quality)


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
