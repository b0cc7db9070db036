"""What the template-tracking classes (Ikaros 3's TemplateMatcher family) pass to each other,
and the geometry they share.

The layouts are this project's reading of the original's interface, which names the ports
but not their contents (docs/vision-tracking.md describes them with a worked model):

- Points (KEYPOINTS, TEMPLATE_KEYPOINTS, ...) are rows (x, y) in pixels of an
  ``image_width`` x ``image_height`` frame, OpenCV's convention: the centre of the pixel in
  row r and column c is (c, r). Points meant for drawing (PATH, LOCATION, BOXES, ...) are
  fractions 0..1 of the width and height (docs/images.md): x = (c + 0.5) / width.
- TEMPLATE_RANGES has one row (first, count) per template: its rows of TEMPLATE_KEYPOINTS.
- TEMPLATE_CORNERS has one row per template: the corners (x, y) of the region it was
  learned from, top-left, top-right, bottom-right, bottom-left (8 values, pixels).
- CORRESPONDENCES has one row (template, keypoint, template keypoint, score) per match:
  the index of the template, of the row of KEYPOINTS and of the row of TEMPLATE_KEYPOINTS.
- INLIERS has one row (keypoint, template keypoint) per correspondence that fits the
  transform.
- A transform (HOMOGRAPHY, TRANSFORM) maps template points to points of the current image.
- RESULT is ``RESULT_SIZE`` values, named in ``RESULT_FIELDS``.

Lists whose length changes are dynamic outputs (docs/writing-modules.md): their rows are
the items, and a fixed-size source (a Constant in a test) is read whole.
"""
from __future__ import annotations

import numpy as np

RESULT_FIELDS = ("found", "template", "points", "inlier_ratio", "mean_error", "mean_score",
                 "area_fraction", "coverage")
RESULT_SIZE = len(RESULT_FIELDS)
FOUND, TEMPLATE, POINTS, INLIER_RATIO, MEAN_ERROR, MEAN_SCORE, AREA, COVERAGE = range(
    RESULT_SIZE)
RESULT_DESCRIPTION = ("(found, template, points, inlier ratio, mean error in pixels, mean "
                      "match score, area fraction, coverage); found is 1 or 0")


def rows(array, columns: int, port: str = "input") -> np.ndarray:
    """The rows of a list input (a dynamic input or a fixed array) as float64, shape
    (n, columns); an empty or unconnected input gives no rows."""
    if array is None:
        return np.zeros((0, columns))
    values = np.asarray(array, dtype=np.float64)
    if values.size == 0:
        return np.zeros((0, columns))
    if values.ndim == 1:
        values = values.reshape(1, -1)
    if values.shape[-1] < columns:
        raise ValueError(f"{port} must have rows of {columns} values, not shape "
                         f"{values.shape}")
    return values.reshape(-1, values.shape[-1])[:, :columns]


def flag(array) -> bool:
    """Whether a one-value control input (LEARN, CLEAR, RESTRICT, ENABLE) is above 0; an
    unconnected one is None and gives False."""
    return array is not None and np.asarray(array).size > 0 and float(
        np.asarray(array).flat[0]) > 0


def found(result) -> bool:
    """Whether a RESULT says a template was found."""
    values = np.asarray(result).ravel()
    return values.size > FOUND and values[FOUND] > 0


def template_ranges(ranges) -> np.ndarray:
    """TEMPLATE_RANGES as integer rows (first, count)."""
    return rows(ranges, 2, "TEMPLATE_RANGES").astype(np.int64)


def central_region(width: float, height: float, fraction: float) -> tuple:
    """(x0, y0, x1, y1): the centred rectangle with ``fraction`` of the width and of the
    height of a width x height frame, in pixel coordinates."""
    fraction = min(max(fraction, 0.0), 1.0)
    half_w, half_h = width * fraction / 2, height * fraction / 2
    cx, cy = (width - 1) / 2, (height - 1) / 2
    return cx - half_w, cy - half_h, cx + half_w, cy + half_h


def inside(points: np.ndarray, region: tuple) -> np.ndarray:
    """A mask of the points (rows x, y) inside the rectangle (x0, y0, x1, y1)."""
    x0, y0, x1, y1 = region
    return ((points[:, 0] >= x0) & (points[:, 0] <= x1) & (points[:, 1] >= y0)
            & (points[:, 1] <= y1))


def rectangle_corners(region: tuple) -> np.ndarray:
    """The corners of a rectangle (x0, y0, x1, y1) as 4 rows (x, y): top-left, top-right,
    bottom-right, bottom-left."""
    x0, y0, x1, y1 = region
    return np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]], np.float64)


def project(homography: np.ndarray, points: np.ndarray) -> np.ndarray:
    """Points (rows x, y) mapped by a 3 x 3 homography (infinite where it sends them to
    the line at infinity)."""
    h = np.asarray(homography, np.float64).reshape(3, 3)
    ones = np.ones((len(points), 1))
    mapped = np.hstack([points, ones]) @ h.T
    with np.errstate(divide="ignore", invalid="ignore"):
        return mapped[:, :2] / mapped[:, 2:3]


def polygon_area(corners: np.ndarray) -> float:
    """The area of a polygon (rows x, y) by the shoelace formula."""
    x, y = corners[:, 0], corners[:, 1]
    return 0.5 * abs(float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))


def is_convex(corners: np.ndarray) -> bool:
    """Whether a polygon (rows x, y, in order) is convex and not degenerate: every turn has
    the same sign."""
    edges = np.roll(corners, -1, axis=0) - corners
    turns = edges[:, 0] * np.roll(edges[:, 1], -1) - edges[:, 1] * np.roll(edges[:, 0], -1)
    return bool(np.all(np.isfinite(turns)) and (np.all(turns > 0) or np.all(turns < 0)))


def plausible_polygon(corners: np.ndarray, width: float, height: float, smallest: float,
                      largest: float) -> tuple[bool, float]:
    """Whether a projected template outline is a convex polygon whose area lies between
    ``smallest`` and ``largest`` fractions of the frame, and that area fraction."""
    if not np.all(np.isfinite(corners)):
        return False, 0.0
    fraction = polygon_area(corners) / (width * height)
    return is_convex(corners) and smallest <= fraction <= largest, fraction


def normalised(points: np.ndarray, width: float, height: float) -> np.ndarray:
    """Pixel points (OpenCV's convention) as fractions 0..1 of the frame (docs/images.md)."""
    return (points + 0.5) / np.array([width, height])


def identity(out: np.ndarray) -> None:
    """Write the 3 x 3 identity (the transform of no change) into ``out``."""
    out[...] = np.eye(3, dtype=np.float32).reshape(out.shape)
