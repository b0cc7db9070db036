"""Ikaros images ((rows, cols) gray or (3, rows, cols) colour, 0..1) to and from the data of
sensor_msgs/Image messages."""
from __future__ import annotations

import numpy as np

IMAGE_ENCODINGS = ["rgb8", "bgr8", "mono8", "32FC1"]


def image_message(values: np.ndarray, encoding: str) -> tuple[int, int, int, bytes]:
    """An Ikaros image ((rows, cols) or (3, rows, cols), 0..1) as (height, width, step,
    data) of a sensor_msgs/Image in ``encoding``."""
    if encoding == "32FC1":
        plane = values if values.ndim == 2 else values.mean(axis=0)
        data = np.ascontiguousarray(plane, "<f4")
        return plane.shape[0], plane.shape[1], plane.shape[1] * 4, data.tobytes()
    scaled = np.clip(np.rint(values * 255.0), 0, 255).astype(np.uint8)
    if encoding == "mono8":
        plane = scaled if scaled.ndim == 2 else np.rint(values.mean(axis=0) * 255.0).clip(
            0, 255).astype(np.uint8)
        return plane.shape[0], plane.shape[1], plane.shape[1], plane.tobytes()
    planes = scaled if scaled.ndim == 3 else np.stack([scaled] * 3)
    if encoding == "bgr8":
        planes = planes[::-1]
    pixels = np.ascontiguousarray(planes.transpose(1, 2, 0))
    return pixels.shape[0], pixels.shape[1], pixels.shape[1] * 3, pixels.tobytes()


def image_values(message: dict, out: np.ndarray) -> str | None:
    """Write a sensor_msgs/Image into the Ikaros image ``out``; an error text when it cannot
    (another size or encoding)."""
    rows, cols, encoding = message["height"], message["width"], message["encoding"]
    if (rows, cols) != out.shape[-2:]:
        return f"an image of {cols}x{rows} came, {out.shape[-1]}x{out.shape[-2]} was expected"
    data = np.frombuffer(message["data"], np.uint8)
    step = message["step"]
    if encoding in ("rgb8", "bgr8"):
        pixels = data.reshape(rows, step)[:, :cols * 3].reshape(rows, cols, 3) / 255.0
        planes = pixels.transpose(2, 0, 1)
        if encoding == "bgr8":
            planes = planes[::-1]
        out[...] = planes if out.ndim == 3 else planes.mean(axis=0)
    elif encoding == "mono8":
        plane = data.reshape(rows, step)[:, :cols] / 255.0
        out[...] = plane if out.ndim == 2 else plane[None]
    elif encoding == "32FC1":
        plane = data.reshape(rows, step)[:, :cols * 4].copy().view("<f4")
        out[...] = plane if out.ndim == 2 else plane[None]
    else:
        return f'the image encoding "{encoding}" is not supported ({", ".join(IMAGE_ENCODINGS)})'
    return None
