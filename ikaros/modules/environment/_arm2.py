"""The Ikaros 2 PlanarArm: three segments in the unit square, and a target to reach."""
import math

import numpy as np

LIMITS_LOW = np.array([-math.pi / 1.5, 0.0, 0.0])
LIMITS_HIGH = np.array([math.pi / 1.5, math.pi, math.pi])
START_ANGLES = 0.4
RANDOM_INTERVAL = 100       # ticks between new random targets
STEP_THRESHOLD = 1.0        # a change this large (radians) or more is taken in steps
BASE = (0.5, 0.0)


def arm_joints(angles, segment_length, base=BASE):
    """Forward kinematics: the (4, 2) joint positions of the arm for three joint angles.

    Angles are measured from the y axis (straight up), clockwise, each relative to the
    previous segment: joint k+1 = joint k + L_k (sin(a_0+...+a_k), cos(a_0+...+a_k))."""
    cumulative = np.cumsum(angles)
    steps = np.stack([np.sin(cumulative), np.cos(cumulative)], axis=1) * \
        np.asarray(segment_length, np.float64)[:, None]
    return np.vstack([base, np.asarray(base) + np.cumsum(steps, axis=0)])


def inside_frame(point) -> bool:
    """Whether a point lies within 0.01 … 0.99 in x and y."""
    return bool(np.all((point >= 0.01) & (point <= 0.99)))


def next_angles(angles, desired, speed):
    """One tick of motion: a largest change of STEP_THRESHOLD or more moves ``speed`` times
    the change, a smaller one reaches the desired angles at once; then the joint limits."""
    change = desired - angles
    if np.abs(change).max() >= STEP_THRESHOLD:
        new = angles + speed * change
    else:
        new = desired.copy()
    return np.clip(new, LIMITS_LOW, LIMITS_HIGH)


def path_target(kind, phase, radius):
    """The target on a path of ``radius`` around (0.5, 0.5) at ``phase`` radians."""
    s, c = math.sin(phase), math.cos(phase)
    if kind == "linear":
        return np.array([0.5 + radius * s, 0.5])
    if kind == "circular":
        return np.array([0.5 + radius * s, 0.5 + radius * c])
    if kind == "lisajous":
        return np.array([0.5 + radius * s, 0.5 + radius * math.cos(0.3 * phase)])
    norm = abs(s) + abs(c)                              # square
    return np.array([0.5 + radius * s / norm, 0.5 + radius * c / norm])
