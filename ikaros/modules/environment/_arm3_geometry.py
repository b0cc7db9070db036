"""Geometry of the Ikaros 3 PlanarArm (MODULES-V3 §26): the arm's segments (links, palm,
fingers) as capsules, distances, and collisions with the fixed world."""
import math
from dataclasses import dataclass

import numpy as np

EPSILON = 1e-5


@dataclass
class Segment:
    a: np.ndarray
    b: np.ndarray
    radius: float

    @property
    def middle(self) -> np.ndarray:
        return (self.a + self.b) / 2


def closest_point(p, a, b) -> np.ndarray:
    """The point of segment a-b closest to p."""
    ab = b - a
    length2 = float(ab @ ab)
    t = 0.0 if length2 == 0 else min(max(float((p - a) @ ab) / length2, 0.0), 1.0)
    return a + t * ab


def point_distance(p, a, b) -> float:
    return float(np.hypot(*(p - closest_point(p, a, b))))


def _cross(o, a, b) -> float:
    return float((a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]))


def _intersect(a, b, c, d) -> bool:
    d1, d2, d3, d4 = _cross(c, d, a), _cross(c, d, b), _cross(a, b, c), _cross(a, b, d)
    return ((d1 > 0) != (d2 > 0)) and ((d3 > 0) != (d4 > 0)) and 0 not in (d1, d2, d3, d4)


def segment_distance(a, b, c, d) -> float:
    """0 when the segments cross, else the least of the four endpoint distances."""
    if _intersect(a, b, c, d):
        return 0.0
    return min(point_distance(a, c, d), point_distance(b, c, d), point_distance(c, a, b),
               point_distance(d, a, b))


def arm_segments(p, angles, gripper) -> list:
    """The L links, the palm and the left and right fingers (in that order)."""
    segments, cursor, theta = [], np.asarray(p.base_position, float), 0.0
    for length, angle in zip(p.link_lengths, angles):
        theta += angle
        end = cursor + length * np.array([math.cos(theta), math.sin(theta)])
        segments.append(Segment(cursor, end, p.link_width / 2))
        cursor = end
    forward = np.array([math.cos(theta), math.sin(theta)])
    side = np.array([-forward[1], forward[0]])
    left, right = cursor + side * p.palm_length / 2, cursor - side * p.palm_length / 2
    phi = -p.finger_closed_angle + min(max(gripper, 0.0), 1.0) * \
        (p.finger_closed_angle + p.finger_open_angle)
    r = p.gripper_width / 2
    segments.append(Segment(left, right, r))
    for start, angle in ((left, theta + phi), (right, theta - phi)):
        segments.append(Segment(start, start + p.finger_length *
                                np.array([math.cos(angle), math.sin(angle)]), r))
    return segments


def hits_fixed(p, segments) -> bool:
    """Whether any segment touches a world edge, a fixed circle or a fixed line."""
    for s in segments:
        for end in (s.a, s.b):
            if end[0] < s.radius or end[1] < s.radius or end[0] > p.world_width - s.radius \
                    or end[1] > p.world_height - s.radius:
                return True
        for cx, cy, cr in p.circles:
            if point_distance(np.array([cx, cy]), s.a, s.b) < cr + s.radius - EPSILON:
                return True
        for x1, y1, x2, y2, width in p.lines:
            if segment_distance(s.a, s.b, np.array([x1, y1]), np.array([x2, y2])) < \
                    width / 2 + s.radius - EPSILON:
                return True
    return False
