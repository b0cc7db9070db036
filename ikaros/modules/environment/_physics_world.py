"""The physics World2D (this project's; Ikaros 2 has no World2D): a pymunk arena with a
two-wheeled robot, round objects it can push, static boxes and range sensors."""
import math

import numpy as np

_ROBOT_GROUP = 1                # the robot's own shape is left out of its sensor rays
_WALL_THICKNESS = 1.0


class PhysicsWorld:
    """The world of one World2D module (``m``), whose parameters and outputs it uses."""

    def __init__(self, m, pymunk):
        self.m = m
        self._pymunk = pymunk
        self._build()
        self._write()

    def object_rows(self):
        rows = np.asarray(self.m.objects, np.float64)
        if rows.size == 0:
            return np.zeros((0, 6))
        rows = rows.reshape(-1, rows.shape[-1]) if rows.ndim > 1 else rows.reshape(1, -1)
        if rows.shape[1] < 4:
            raise ValueError("each row of objects needs x, y, radius and mass")
        return np.hstack([rows[:, :6], np.zeros((len(rows), max(0, 6 - rows.shape[1])))])

    def obstacle_rows(self):
        rows = np.asarray(self.m.obstacles, np.float64)
        if rows.size == 0:
            return np.zeros((0, 4))
        if rows.size % 4:
            raise ValueError("each row of obstacles needs x0, y0, x1, y1")
        return rows.reshape(-1, 4)

    def _build(self):
        pm = self._pymunk
        space = pm.Space()
        space.gravity = tuple(float(g) for g in (list(self.m.gravity) + [0, 0])[:2])
        space.damping = float(self.m.damping)
        space.collision_slop = 0.0005
        space.iterations = 20
        self._space = space
        w, h, t = float(self.m.width), float(self.m.height), _WALL_THICKNESS
        walls = [(-t, -t, 0, h + t), (w, -t, w + t, h + t), (0, -t, w, 0), (0, h, w, h + t)]
        segments = [(0, 0, w, 0), (w, 0, w, h), (w, h, 0, h), (0, h, 0, 0)]
        for x0, y0, x1, y1 in self.obstacle_rows():
            x0, x1 = sorted((x0, x1))
            y0, y1 = sorted((y0, y1))
            walls.append((x0, y0, x1, y1))
            segments += [(x0, y0, x1, y0), (x1, y0, x1, y1), (x1, y1, x0, y1), (x0, y1, x0, y0)]
        for x0, y0, x1, y1 in walls:
            box = pm.Poly(space.static_body, [(x0, y0), (x1, y0), (x1, y1), (x0, y1)])
            self._material(box)
            space.add(box)
        self.m.WALLS[...] = np.array(segments, np.float32)

        r, m = float(self.m.robot_radius), float(self.m.robot_mass)
        self._robot = pm.Body(m, pm.moment_for_circle(m, 0, r))
        self._robot.position = (float(self.m.robot_x), float(self.m.robot_y))
        self._robot.angle = float(self.m.robot_heading)
        self._robot_shape = pm.Circle(self._robot, r)
        self._robot_shape.filter = pm.ShapeFilter(group=_ROBOT_GROUP)
        self._material(self._robot_shape)
        space.add(self._robot, self._robot_shape)
        if self.m.MOVE is not None:
            # The wheels act through two velocity constraints of limited force between the
            # robot and a kinematic control body (so walls and heavy objects can stop it).
            self._control = pm.Body(body_type=pm.Body.KINEMATIC)
            self._control.position = self._robot.position
            pivot = pm.PivotJoint(self._control, self._robot, (0, 0), (0, 0))
            pivot.max_bias = 0
            pivot.max_force = float(self.m.drive_force)
            gear = pm.GearJoint(self._control, self._robot, 0.0, 1.0)
            gear.error_bias = 0
            gear.max_bias = 0
            gear.max_force = float(self.m.drive_force) * r
            space.add(self._control, pivot, gear)

        self._bodies = []
        self._radii = []
        for x, y, radius, mass, vx, vy in self.object_rows():
            body = pm.Body(float(mass), pm.moment_for_circle(float(mass), 0, float(radius)))
            body.position = (float(x), float(y))
            body.velocity = (float(vx), float(vy))
            shape = pm.Circle(body, float(radius))
            self._material(shape)
            space.add(body, shape)
            self._bodies.append(body)
            self._radii.append(float(radius))

    def _material(self, shape):
        shape.elasticity = float(self.m.elasticity)
        shape.friction = float(self.m.friction)

    def step(self):
        dt = float(self.m.time_step) if self.m.time_step and self.m.time_step > 0 \
            else float(self.m.clock.tick_duration)
        n = max(int(self.m.substeps), 1)
        self._space.damping = float(self.m.damping)
        for _ in range(n):
            self._drive()
            self._space.step(dt / n)
        self._write()

    def _drive(self):
        if self.m.MOVE is None:
            return
        left, right = np.clip(np.asarray(self.m.MOVE, np.float64).reshape(-1)[:2],
                              -self.m.max_speed, self.m.max_speed)
        v = 0.5 * (left + right)
        a = self._robot.angle
        self._control.velocity = (v * math.cos(a), v * math.sin(a))
        self._control.angular_velocity = (right - left) / self.m.wheel_base \
            if self.m.wheel_base > 0 else 0.0

    # --- outputs ------------------------------------------------------------------------
    def _write(self):
        robot = self._robot
        x, y = robot.position
        a = robot.angle
        self.m.POSE[...] = (x, y, (a + math.pi) % (2 * math.pi) - math.pi)
        self.m.VELOCITY[...] = (robot.velocity[0], robot.velocity[1], robot.angular_velocity)
        bodies = [robot] + self._bodies
        masses = np.array([b.mass for b in bodies])
        velocities = np.array([tuple(b.velocity) for b in bodies])
        spins = np.array([b.angular_velocity for b in bodies])
        moments = np.array([b.moment for b in bodies])
        self.m.MOMENTUM[...] = masses @ velocities
        self.m.ENERGY[0] = 0.5 * (masses @ (velocities ** 2).sum(axis=1) + moments @ spins ** 2)
        if self._bodies:
            self.m.OBJECTS[:, 0:2] = [tuple(b.position) for b in self._bodies]
            self.m.OBJECTS[:, 2] = [b.angle for b in self._bodies]
            self.m.OBJECTS[:, 3] = self._radii
            self.m.OBJECT_VELOCITIES[:, 0:2] = velocities[1:]
            self.m.OBJECT_VELOCITIES[:, 2] = spins[1:]
        else:
            self.m.OBJECTS.fill(0)
            self.m.OBJECT_VELOCITIES.fill(0)
        self._sense(x, y, a)
        self.m.COLLISION[0] = 1.0 if self._space.shape_query(self._robot_shape) else 0.0

    def _sense(self, x, y, a):
        r = float(self.m.robot_radius)
        reach = max(float(self.m.sensor_range), 0.0)
        pm_filter = self._pymunk.ShapeFilter(group=_ROBOT_GROUP)
        directions = a + np.asarray(self.m.sensor_angles, np.float64).reshape(-1)
        for i, d in enumerate(directions):
            ux, uy = math.cos(d), math.sin(d)
            start = (x + r * ux, y + r * uy)
            end = (start[0] + reach * ux, start[1] + reach * uy)
            hit = self._space.segment_query_first(start, end, 0, pm_filter) if reach > 0 \
                else None
            distance = reach * hit.alpha if hit is not None else reach
            self.m.RANGES[i] = distance
            self.m.RANGE_POINTS[i] = (start[0] + distance * ux, start[1] + distance * uy)
