"""GLRobotSimulator's RANGE_MAP as Ikaros 2 computes it: the nearest wall point in each of
32 sectors around the robot, in single precision.

The walls are the points of whole millimetres along the four sides of the arena. Each point
goes to the sector ``32 - trunc((angle - heading + pi) / (2 pi / 32))`` (brought into
0 .. 31 by adding or subtracting 32 once; a point still outside is not counted), so sector
16 is the one just counter-clockwise of the heading, the sectors run clockwise, and sector 0
is behind the robot, made wider by the truncation towards 0 (with ``even`` the quotient is
rounded down instead, so every sector spans 2 pi / 32). A sector holds the distance of its
nearest point, or the limit when it has none nearer. Those rules are what the golden files
of Ikaros 2 show, to the last digit.
"""
import math

import numpy as np

SECTORS = 32
_PI = np.float32(math.pi)
_WIDTH = np.float32(2 * math.pi / SECTORS)


def wall_points(width: float, depth: float) -> np.ndarray:
    """The points (x, y) of whole millimetres along the walls of a width x depth arena."""
    xs = np.arange(0, int(width) + 1, dtype=np.float32)
    ys = np.arange(1, int(depth), dtype=np.float32)
    w, d = np.float32(int(width)), np.float32(int(depth))
    return np.concatenate([np.stack([xs, np.zeros_like(xs)], 1),
                           np.stack([xs, np.full_like(xs, d)], 1),
                           np.stack([np.zeros_like(ys), ys], 1),
                           np.stack([np.full_like(ys, w), ys], 1)])


def sectors(dx: np.ndarray, dy: np.ndarray, heading: float, even=False) -> np.ndarray:
    """The sector of each offset (dx, dy) from the robot; -1 where none."""
    angle = np.arctan2(dy.astype(np.float32), dx.astype(np.float32))
    q = (angle - np.float32(heading) + _PI) / _WIDTH
    index = SECTORS - (np.floor(q) if even else np.trunc(q)).astype(np.int64)
    index = np.where(index < 0, index + SECTORS, index)
    index = np.where(index >= SECTORS, index - SECTORS, index)
    return np.where((index >= 0) & (index < SECTORS), index, -1)


def range_map(walls: np.ndarray, x: float, y: float, heading: float, limit: float,
              objects=None, even=False):
    """(ranges, colours) of the 32 sectors: the nearest wall point, or object given as rows
    (x, y, radius, colour) counted at its centre's sector with its centre distance less its
    radius; colour 0 for a wall or nothing."""
    ranges = np.full(SECTORS, np.float32(limit), np.float32)
    colours = np.zeros(SECTORS, np.float32)
    dx = walls[:, 0] - np.float32(x)
    dy = walls[:, 1] - np.float32(y)
    index = sectors(dx, dy, heading, even)
    inside = index >= 0
    np.minimum.at(ranges, index[inside], np.sqrt(dx * dx + dy * dy)[inside])
    if objects is not None and len(objects):
        objects = np.asarray(objects, np.float32)
        ox, oy = objects[:, 0] - np.float32(x), objects[:, 1] - np.float32(y)
        distance = np.maximum(np.sqrt(ox * ox + oy * oy) - objects[:, 2], 0)
        for k, d, colour in zip(sectors(ox, oy, heading, even), distance, objects[:, 3]):
            if k >= 0 and d < ranges[k]:
                ranges[k], colours[k] = d, colour
    return ranges, colours
