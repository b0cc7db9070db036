"""RGB-D recordings: the stand-in for a depth camera (the Kinect module plays them).

A recording is a NumPy .npz file with two arrays: ``rgb``, (frames, rows, cols, 3) uint8,
and ``depth``, (frames, rows, cols) uint16 Kinect raw 11-bit values (0..2046; 2047 is no
reading). ``save_recording`` writes one; ``synthetic_recording`` makes one with a known
answer: a wall at ``wall`` mm and a box at ``box`` mm moving from left to right.
"""
from __future__ import annotations

import numpy as np


def raw_to_mm(raw: np.ndarray) -> np.ndarray:
    """Kinect (version 1) 11-bit raw depth to millimetres with the usual fitted model
    1000 / (3.3309495161 - 0.0030711016 · raw); 2047 (no reading) and values that give no
    positive depth become 0."""
    raw = np.asarray(raw, np.float32)
    denominator = np.float32(3.3309495161) - np.float32(0.0030711016) * raw
    mm = np.zeros(raw.shape, np.float32)
    np.divide(1000.0, denominator, out=mm, where=(denominator > 0) & (raw < 2047))
    return mm


def mm_to_raw(mm: np.ndarray) -> np.ndarray:
    """The inverse of raw_to_mm (0 mm, no reading, becomes 2047)."""
    mm = np.asarray(mm, np.float64)
    raw = np.full(mm.shape, 2047.0)
    np.divide(3.3309495161 - 1000.0 / np.where(mm > 0, mm, 1), 0.0030711016, out=raw,
              where=mm > 0)
    return np.clip(np.rint(raw), 0, 2047).astype(np.uint16)


def save_recording(path, rgb: np.ndarray, depth_raw: np.ndarray) -> None:
    """Write a recording: rgb (frames, rows, cols, 3) uint8, depth (frames, rows, cols) raw."""
    rgb, depth = np.asarray(rgb, np.uint8), np.asarray(depth_raw, np.uint16)
    if rgb.ndim != 4 or rgb.shape[-1] != 3 or depth.shape != rgb.shape[:3]:
        raise ValueError(f"rgb must be (frames, rows, cols, 3) and depth (frames, rows, "
                         f"cols), not {rgb.shape} and {depth.shape}")
    np.savez_compressed(path, rgb=rgb, depth=depth)


def box_columns(frame: int, frames: int, cols: int, width: int) -> tuple[int, int]:
    """The first and last + 1 column of the box in a frame of synthetic_recording."""
    left = int(round((cols - width) * frame / max(1, frames - 1)))
    return left, left + width


def synthetic_recording(path, frames: int = 8, rows: int = 120, cols: int = 160,
                        wall: float = 3000.0, box: float = 1500.0) -> None:
    """A recording of a gray wall at ``wall`` mm and a red box at ``box`` mm, a quarter of
    the width wide and the middle half of the height tall, moving from the left edge to the
    right edge (box_columns gives its columns)."""
    width = cols // 4
    rgb = np.full((frames, rows, cols, 3), 120, np.uint8)
    depth = np.full((frames, rows, cols), mm_to_raw(np.array(wall)), np.uint16)
    top, bottom = rows // 4, rows - rows // 4
    for k in range(frames):
        left, right = box_columns(k, frames, cols, width)
        rgb[k, top:bottom, left:right] = (200, 40, 40)
        depth[k, top:bottom, left:right] = mm_to_raw(np.array(box))
    save_recording(path, rgb, depth)
