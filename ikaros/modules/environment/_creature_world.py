"""The Ikaros 3 World2D as this project reads its interface: a differential-drive creature
with whiskers and odour sensors among food, aversive objects and walls.

Objects (``food`` and ``aversive`` rows): id, x, y, radius, value, red, green, blue, opaque,
then 8 smell channels. Walls (``walls`` rows): id, x1, y1, x2, y2, red, green, blue, opaque,
width, solid. Headings are radians from the +x axis towards +y.
"""
import math

import numpy as np

from ._arm3_geometry import closest_point, point_distance as segment_distance

OBJECT_COLUMNS, WALL_COLUMNS, SMELLS = 17, 11, 8
FOOD, AVERSIVE = 1.0, 2.0            # the type column of the OBJECTS output
TOUCH = 1e-3                         # distances this close count as touching
_EPS = 1e-9


def rows(value, columns, name):
    """A matrix parameter as rows of ``columns`` values (none for an empty or zero one)."""
    data = np.asarray(value, np.float64)
    if data.size == 0 or (data.size == 1 and float(data.flat[0]) == 0):
        return np.zeros((0, columns))
    if data.size % columns:
        raise ValueError(f"{name} has {data.size} values: it needs rows of {columns}")
    return data.reshape(-1, columns).copy()


def ray_circle(origin, direction, centre, radius) -> float | None:
    """The distance along a unit ray to a circle (0 when it starts inside), or None."""
    f = origin - centre
    b = float(f @ direction)
    c = float(f @ f) - radius * radius
    if c <= 0:
        return 0.0
    disc = b * b - c
    if disc < 0 or -b - math.sqrt(disc) < 0:
        return None
    return -b - math.sqrt(disc)


def ray_capsule(origin, direction, a, b, radius) -> float | None:
    """The distance along a unit ray to a segment widened by ``radius`` (0 when it starts
    inside), or None: the nearer of its end circles and its two straight sides."""
    length = float(np.hypot(*(b - a)))
    hits = [ray_circle(origin, direction, a, radius), ray_circle(origin, direction, b, radius)]
    if length > 0:
        along = (b - a) / length
        normal = np.array([-along[1], along[0]])
        x0, y0 = float((origin - a) @ along), float((origin - a) @ normal)
        if abs(y0) <= radius and 0 <= x0 <= length:
            return 0.0
        dy, dx = float(direction @ normal), float(direction @ along)
        for side in (radius, -radius):
            if dy != 0:
                s = (side - y0) / dy
                if s >= 0 and 0 <= x0 + s * dx <= length:
                    hits.append(s)
    hits = [h for h in hits if h is not None]
    return min(hits) if hits else None


class CreatureWorld:
    """The state of the world and one tick of the creature."""

    def __init__(self, p):
        self.p = p
        self.objects = np.vstack([rows(p.food, OBJECT_COLUMNS, "food"),
                                  rows(p.aversive, OBJECT_COLUMNS, "aversive")])
        self.kinds = np.array([FOOD] * len(rows(p.food, OBJECT_COLUMNS, "food")) +
                              [AVERSIVE] * len(rows(p.aversive, OBJECT_COLUMNS, "aversive")))
        self.walls = rows(p.walls, WALL_COLUMNS, "walls")
        solid = self.objects[self.objects[:, 8] > 0] if len(self.objects) else self.objects
        self._circles = solid[:, 1:4]                              # x, y, radius
        self._ends = self.walls[:, 1:3], self.walls[:, 3:5]
        self._half_widths = self.walls[:, 9] / 2
        self.reset()

    def reset(self):
        p = self.p
        self.x, self.y, self.heading = float(p.creature_x), float(p.creature_y), \
            float(p.creature_heading)
        self.contact = np.zeros(2)
        self.whiskers = np.zeros(2)
        self.reward = self.punishment = 0.0
        self.sense()

    # --- geometry -----------------------------------------------------------------------
    def _solids(self):
        """(centre, radius) of the opaque objects and (a, b, half width) of the walls."""
        circles = [(o[1:3], o[3]) for o in self.objects if o[8] > 0]
        capsules = [(w[1:3], w[3:5], w[9] / 2) for w in self.walls]
        return circles, capsules

    def _clearance(self, point) -> float:
        """How far the creature's body at ``point`` is from every solid thing and the edge of
        the world (negative: overlapping)."""
        r, p = self.p.creature_radius, self.p
        gap = min(point[0], point[1], p.world_width - point[0], p.world_height - point[1]) - r
        if len(self._circles):
            centres, radii = self._circles[:, :2], self._circles[:, 2]
            gap = min(gap, float(np.min(np.hypot(*(point - centres).T) - radii)) - r)
        if len(self._half_widths):
            a, b = self._ends
            ab = b - a
            length2 = np.maximum((ab * ab).sum(axis=1), 1e-300)
            t = np.clip(((point - a) * ab).sum(axis=1) / length2, 0.0, 1.0)
            nearest = a + t[:, None] * ab
            gap = min(gap, float(np.min(np.hypot(*(point - nearest).T) - self._half_widths))
                      - r)
        return gap

    def _pose_after(self, fraction, left, right):
        """The pose after ``fraction`` of this tick's wheel travel (an arc)."""
        p = self.p
        d_left = 2 * math.pi * p.wheel_radius * left * fraction
        d_right = 2 * math.pi * p.wheel_radius * right * fraction
        distance = 0.5 * (d_left + d_right)
        turn = (d_right - d_left) / p.wheel_base if p.wheel_base > 0 else 0.0
        h = self.heading
        if abs(turn) < 1e-12:
            x, y = self.x + distance * math.cos(h), self.y + distance * math.sin(h)
        else:
            radius = distance / turn
            x = self.x + radius * (math.sin(h + turn) - math.sin(h))
            y = self.y - radius * (math.cos(h + turn) - math.cos(h))
        return x, y, h + turn

    # --- a tick -------------------------------------------------------------------------
    def move(self, motor):
        """Drive: MOTOR is wheel rotations per tick (left, right), clipped to max_motor_rpt;
        the creature goes as far along its arc as it can without overlapping a wall, an
        opaque object or the edge of the world."""
        if motor is None:
            return
        limit = max(float(self.p.max_motor_rpt), 0.0)
        left, right = np.clip(np.asarray(motor, np.float64).reshape(-1)[:2], -limit, limit)

        def free(fraction):
            x, y, _ = self._pose_after(fraction, left, right)
            return self._clearance(np.array([x, y])) >= -_EPS
        fraction = 1.0
        if not free(1.0):
            low, high = 0.0, 1.0
            for _ in range(30):
                middle = 0.5 * (low + high)
                low, high = (middle, high) if free(middle) else (low, middle)
            fraction = low
        x, y, heading = self._pose_after(fraction, left, right)
        if fraction < 1.0:           # blocked: the rest of the turn happens in place
            heading = self._pose_after(1.0, left, right)[2]
        self.x, self.y = x, y
        self.heading = (heading + math.pi) % (2 * math.pi) - math.pi

    def sense(self):
        r = self.p.creature_radius
        centre = np.array([self.x, self.y])
        self.contact = np.zeros(2)
        circles, capsules = self._solids()
        touching = [c for c, cr in circles if np.hypot(*(centre - c)) - cr - r <= TOUCH]
        for a, b, w in capsules:
            if segment_distance(centre, a, b) - w - r <= TOUCH:
                touching.append(closest_point(centre, a, b))
        for point in touching + self._edges(centre, r):
            side = math.sin(math.atan2(point[1] - self.y, point[0] - self.x) - self.heading)
            if side > -1e-6:                # left: towards +heading; straight ahead: both
                self.contact[0] = 1.0
            if side < 1e-6:
                self.contact[1] = 1.0
        values = self.objects[:, 4] if len(self.objects) else np.zeros(0)
        near = [k for k, o in enumerate(self.objects)
                if np.hypot(*(centre - o[1:3])) - o[3] - r <= TOUCH]
        self.reward = float(sum(max(values[k], 0.0) for k in near))
        self.punishment = float(sum(max(-values[k], 0.0) for k in near))
        self.whiskers = np.array([self._whisker(side) for side in (1, -1)])
        self.odour = np.array([self._odour(side) for side in (1, -1)])

    def _edges(self, centre, r):
        """Points of the world's edge the body touches."""
        p, points = self.p, []
        for touching, point in ((centre[0] - r <= TOUCH, (0.0, centre[1])),
                                (centre[1] - r <= TOUCH, (centre[0], 0.0)),
                                (p.world_width - r - centre[0] <= TOUCH,
                                 (p.world_width, centre[1])),
                                (p.world_height - r - centre[1] <= TOUCH,
                                 (centre[0], p.world_height))):
            if touching:
                points.append(np.array(point))
        return points

    def whisker_base(self, side):
        """The whisker's root on the rim (side 1 left, -1 right) and its direction."""
        angle = self.heading + side * self.p.whisker_angle
        direction = np.array([math.cos(angle), math.sin(angle)])
        return np.array([self.x, self.y]) + self.p.creature_radius * direction, direction

    def _whisker(self, side) -> float:
        """1 - the distance along the whisker to the first wall, opaque object or edge of
        the world / its length; 0 when nothing is within reach."""
        reach = float(self.p.whisker_length)
        if reach <= 0:
            return 0.0
        origin, direction = self.whisker_base(side)
        circles, capsules = self._solids()
        hits = [ray_circle(origin, direction, c, cr) for c, cr in circles]
        hits += [ray_capsule(origin, direction, a, b, w) for a, b, w in capsules]
        hits += [self._ray_edge(origin, direction)]
        nearest = min((h for h in hits if h is not None and h <= reach), default=None)
        return 0.0 if nearest is None else 1.0 - nearest / reach

    def _ray_edge(self, origin, direction):
        p, distances = self.p, []
        for axis, size in ((0, p.world_width), (1, p.world_height)):
            if direction[axis] > 0:
                distances.append((size - origin[axis]) / direction[axis])
            elif direction[axis] < 0:
                distances.append(-origin[axis] / direction[axis])
        return max(min(distances), 0.0) if distances else None

    def _odour(self, side) -> np.ndarray:
        """The smell at the whisker's root: each object's smell channels times
        exp(-odour_decay × the distance to its edge)."""
        origin, _ = self.whisker_base(side)
        total = np.zeros(SMELLS)
        for o in self.objects:
            d = max(float(np.hypot(*(origin - o[1:3]))) - o[3], 0.0)
            total += o[9:9 + SMELLS] * math.exp(-self.p.odour_decay * d)
        return total
