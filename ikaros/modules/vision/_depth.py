"""Shared by the depth modules: depth pixels to points.

Points are in the Ikaros frame of the camera: x forward (the depth), y to the left, z up.
A pixel (row r, column c) of a rows x cols image looks along the angles
((c + 0.5) / cols - 0.5) · fov_h to the right and (0.5 - (r + 0.5) / rows) · fov_v up.
"""
import numpy as np


def pixel_angles(rows: int, cols: int, fov_h: float, fov_v: float):
    """tan of the right and up angles of every pixel, as (rows, 1) and (1, cols) arrays."""
    right = np.tan(((np.arange(cols) + 0.5) / cols - 0.5) * fov_h)[None, :]
    up = np.tan((0.5 - (np.arange(rows) + 0.5) / rows) * fov_v)[:, None]
    return right.astype(np.float32), up.astype(np.float32)


def to_points(x, y, depth, x_res, y_res, fov_h, fov_v):
    """Points (forward, left, up) of image positions x (column) and y (row) at a depth."""
    right = np.tan(((x + 0.5) / x_res - 0.5) * fov_h)
    up = np.tan((0.5 - (y + 0.5) / y_res) * fov_v)
    return depth, -depth * right, depth * up
