"""The Ikaros 3 PlanarArm (MODULES-V3 §26): a serial arm with a two-finger gripper that
pushes one movable circle among fixed circles and lines."""
import math
from types import SimpleNamespace

import numpy as np

from ._arm3_geometry import EPSILON, arm_segments, closest_point, hits_fixed, point_distance

LINK_COLOUR, GRIPPER_COLOUR, WALL_COLOUR = (0.12, 0.35, 0.75), (0.15, 0.55, 0.95), \
    (0.25, 0.25, 0.27)
CIRCLE_COLOUR, HELD_COLOUR, FREE_COLOUR = (0.42, 0.42, 0.46), (0.20, 0.85, 0.18), \
    (0.95, 0.55, 0.18)

def _push(centre, point, need, fallback):
    """The centre moved out to distance ``need`` from ``point``, and whether it moved."""
    d = float(np.hypot(*(centre - point)))
    if need - d <= 1e-9:
        return centre, False
    direction = (centre - point) / d if d > 0 else fallback
    return point + direction * need, True


def parameters(m) -> SimpleNamespace:
    """The Ikaros 3 parameters of a PlanarArm module, as plain numbers and arrays."""
    def array(name):
        return np.asarray(getattr(m, name), float).reshape(-1)
    L = array("link_lengths").size

    def per_joint(name):
        values = array(name)
        return np.resize(values, L) if values.size else np.zeros(L)
    circles = np.asarray(m.circle_obstacles, float).reshape(-1, 3)[:int(m.circle_obstacle_count)]
    lines = np.asarray(m.line_obstacles, float).reshape(-1, 5)[:int(m.line_obstacle_count)]
    return SimpleNamespace(
        base_position=array("base_position")[:2], link_lengths=array("link_lengths"),
        link_width=m.link_width, initial_joint_angles=per_joint("initial_joint_angles"),
        joint_min=per_joint("joint_min"), joint_max=per_joint("joint_max"),
        max_joint_step=m.max_joint_step, initial_gripper=m.initial_gripper,
        palm_length=m.palm_length, finger_length=m.finger_length,
        gripper_width=m.gripper_width, finger_open_angle=m.finger_open_angle,
        finger_closed_angle=m.finger_closed_angle,
        movable_object=array("movable_object")[:3], circles=[tuple(c) for c in circles],
        lines=[tuple(line) for line in lines], world_width=m.world_width,
        world_height=m.world_height, solver_iterations=m.solver_iterations)


class Arm3:
    """The arm's state (angles, gripper, object) and its per-tick motion."""

    def __init__(self, p):
        self.p = p
        self.L = len(p.link_lengths)
        self.flags = (np.zeros(self.L), np.zeros(3), np.zeros(4))
        self.reset()

    def reset(self):
        p = self.p
        self.angles = np.clip(p.initial_joint_angles, p.joint_min, p.joint_max)
        self.gripper = min(max(p.initial_gripper, 0.0), 1.0)
        self.object = np.array(p.movable_object[:2], float)
        self.segments = arm_segments(p, self.angles, self.gripper)
        self.blocked = hits_fixed(p, self.segments)
        if not self.blocked:
            solved = self.solve(self.segments, self.segments)
            self.blocked = solved is None
            if solved is not None:
                self.object = solved

    def solve(self, segments, previous):
        """The object's centre pushed out of the arm and the fixed world, or None when it
        cannot be placed. Sets the contact flags of the pushes."""
        p, r = self.p, self.p.movable_object[2]
        links, grip, objects = self.flags
        c = self.object.copy()
        for _ in range(int(p.solver_iterations)):
            changed = False
            for k, (s, old) in enumerate(zip(segments, previous)):
                fallback = s.middle - old.middle
                if not fallback.any():
                    direction = s.b - s.a
                    fallback = np.array([-direction[1], direction[0]])
                fallback = fallback / (np.hypot(*fallback) or 1.0)
                c, moved = _push(c, closest_point(c, s.a, s.b), r + s.radius, fallback)
                if moved:
                    changed = True
                    (links if k < self.L else grip)[k if k < self.L else k - self.L] = 1
                    objects[0] = 1
            for cx, cy, cr in p.circles:
                c, moved = _push(c, np.array([cx, cy]), r + cr, np.array([1.0, 0.0]))
                changed |= moved
                objects[1] = max(objects[1], moved)
            for x1, y1, x2, y2, width in p.lines:
                point = closest_point(c, np.array([x1, y1]), np.array([x2, y2]))
                c, moved = _push(c, point, r + width / 2, np.array([1.0, 0.0]))
                changed |= moved
                objects[2] = max(objects[2], moved)
            clamped = np.clip(c, [r, r], [p.world_width - r, p.world_height - r])
            if np.abs(clamped - c).max() > EPSILON:
                objects[3] = 1
                changed = True
            c = clamped
            if not changed:
                break
        return c if self._valid(c, segments) else None

    def _valid(self, c, segments) -> bool:
        p, r = self.p, self.p.movable_object[2]
        arm_tolerance = max(1e-3, 0.025 * r)
        if any(r + s.radius - point_distance(c, s.a, s.b) > arm_tolerance for s in segments):
            return False
        if any(r + cr - math.hypot(c[0] - cx, c[1] - cy) > 1e-3 for cx, cy, cr in p.circles):
            return False
        if any(r + w / 2 - point_distance(c, np.array([x1, y1]), np.array([x2, y2])) > 1e-3
               for x1, y1, x2, y2, w in p.lines):
            return False
        return r - EPSILON <= c[0] <= p.world_width - r + EPSILON and \
            r - EPSILON <= c[1] <= p.world_height - r + EPSILON

    def move(self, command, gripper_command):
        """One tick: towards the commanded angles and gripper in sub-steps of at most
        max_joint_step, stopping at the first blocked one."""
        p = self.p
        target = self.angles if command is None else \
            np.clip(command[:self.L], p.joint_min, p.joint_max)
        grip_target = self.gripper if gripper_command is None else \
            min(max(gripper_command, 0.0), 1.0)
        change = max(np.abs(target - self.angles).max(initial=0.0),
                     abs(grip_target - self.gripper))
        steps = max(1, math.ceil(change / p.max_joint_step)) if p.max_joint_step > 0 else 1
        for flags in self.flags:
            flags[...] = 0
        self.blocked = False
        start, grip_start = self.angles.copy(), self.gripper
        for s in range(1, steps + 1):
            f = s / steps
            angles = start + (target - start) * f
            gripper = grip_start + (grip_target - grip_start) * f
            segments = arm_segments(p, angles, gripper)
            if hits_fixed(p, segments):
                self.blocked = True
                break
            solved = self.solve(segments, self.segments)
            if solved is None:
                self.blocked = True
                break
            self.angles, self.gripper, self.segments, self.object = \
                angles, gripper, segments, solved

    def sense(self):
        """The contact flags of the accepted state (within 1e-3)."""
        p, r, c = self.p, self.p.movable_object[2], self.object
        links, grip, objects = self.flags
        for k, s in enumerate(self.segments):
            if point_distance(c, s.a, s.b) <= r + s.radius + 1e-3:
                (links if k < self.L else grip)[k if k < self.L else k - self.L] = 1
                objects[0] = 1
        if any(math.hypot(c[0] - cx, c[1] - cy) <= r + cr + 1e-3 for cx, cy, cr in p.circles):
            objects[1] = 1
        if any(point_distance(c, np.array([x1, y1]), np.array([x2, y2])) <= r + w / 2 + 1e-3
               for x1, y1, x2, y2, w in p.lines):
            objects[2] = 1
        if min(c[0] - r, c[1] - r, p.world_width - r - c[0], p.world_height - r - c[1]) <= 1e-3:
            objects[3] = 1

    def write(self, m):
        """Writes the state to the module's Ikaros 3 outputs."""
        L = self.L
        m.JOINT_ANGLES[...] = self.angles
        m.JOINT_POSITIONS[...] = [self.segments[0].a] + [s.b for s in self.segments[:L]]
        hand = self.segments[L - 1].b
        m.END_EFFECTOR[...] = (hand[0], hand[1], self.angles.sum())
        enclosed = float(self.flags[1].sum() >= 2)
        r = self.p.movable_object[2]
        m.MOVABLE_OBJECT[...] = (self.object[0], self.object[1], r, enclosed)
        m.LINK_CONTACTS[...], m.GRIPPER_CONTACTS[...], m.OBJECT_CONTACTS[...] = self.flags
        m.BLOCKED[0], m.ENCLOSED[0] = float(self.blocked), enclosed
        rows = [[k + 1, 1, *s.a, *s.b, *(LINK_COLOUR if k < L else GRIPPER_COLOUR), 1,
                 2 * s.radius] for k, s in enumerate(self.segments)]
        m.ARM_LINES[...] = rows
        walls = rows + [[len(rows) + k + 1, 1, x1, y1, x2, y2, *WALL_COLOUR, 1, w]
                        for k, (x1, y1, x2, y2, w) in enumerate(self.p.lines)]
        m.WALLS[...] = walls
        m.OBJECTS[...] = 0
        m.OBJECTS[0, :10] = (1, 1, self.object[0], self.object[1], r, 0,
                             *(HELD_COLOUR if enclosed else FREE_COLOUR), 1)
        for k, (cx, cy, cr) in enumerate(self.p.circles):
            m.OBJECTS[k + 1, :10] = (k + 2, 3, cx, cy, cr, 0, *CIRCLE_COLOUR, 1)
