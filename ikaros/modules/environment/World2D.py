"""World2D: a 2-D physics world (pymunk) with a two-wheeled robot, objects and range sensors."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter, require

_ROBOT_GROUP = 1                # the robot's own shape is left out of its sensor rays
_WALL_THICKNESS = 1.0


class World2D(Module):
    """A rectangular arena of ``width`` x ``height`` metres seen from above (x to the right,
    y up, angles counter-clockwise from the x axis), simulated with the pymunk rigid-body
    engine (the paper's worlds used Box2D). It holds a round robot with two wheels, round
    objects that it can push, and static box obstacles. MOVE gives the robot's left and
    right wheel speeds in m/s (clipped to ``max_speed``): its forward speed is their mean
    and it turns at (right - left) / ``wheel_base`` rad/s, reached with at most
    ``drive_force`` (so walls and heavy objects stop it); unconnected, the robot is a free
    body like the objects. The robot's range sensors cast rays from its rim at
    ``sensor_angles`` (relative to its heading) and report the distance to the nearest wall,
    obstacle or object, or ``sensor_range`` when nothing is closer. Each tick advances the
    world by ``time_step`` seconds (0: the model's tick_duration) in ``substeps`` steps.
    Every shape has the same ``elasticity`` (1 = elastic) and ``friction``; ``damping`` is
    the fraction of their velocity that bodies keep per second (1 = none lost, as on ice;
    floor friction of the top-down view). MOMENTUM and ENERGY are the total linear momentum
    and kinetic energy of the robot and the objects, so that losses can be watched. WALLS
    lists the arena edges and obstacle edges as line segments, for drawing."""

    width = Parameter(4.0, "width of the arena (x), metres")
    height = Parameter(3.0, "height of the arena (y), metres")
    robot_x = Parameter(1.0, "the robot's starting x")
    robot_y = Parameter(1.5, "the robot's starting y")
    robot_heading = Parameter(0.0, "the robot's starting heading, radians counter-clockwise "
                              "from the x axis")
    robot_radius = Parameter(0.15, "radius of the robot's round body, metres")
    robot_mass = Parameter(5.0, "mass of the robot, kg")
    wheel_base = Parameter(0.3, "distance between the robot's wheels, metres")
    max_speed = Parameter(1.0, "largest wheel speed, m/s")
    drive_force = Parameter(500.0, "the largest force, N, the wheels use to reach the "
                            "commanded speed (the largest torque is this times the radius)")
    objects = Parameter("2.5 1.5 0.1 0.5; 3.0 2.2 0.15 1.0", "round objects, one row each: "
                        "x, y, radius, mass, and optionally vx, vy (start velocity); empty "
                        "for none", type="matrix")
    obstacles = Parameter("", "static boxes, one row each: x0, y0, x1, y1 (opposite "
                          "corners); empty for none", type="matrix")
    elasticity = Parameter(0.5, "elasticity of every shape: 0 inelastic .. 1 elastic")
    friction = Parameter(0.5, "friction coefficient between shapes")
    damping = Parameter(0.5, "fraction of velocity a body keeps after one second (1: none "
                        "lost)", range=(0, 1))
    gravity = Parameter("0 0", "gravity (gx, gy) in m/s^2; 0 0 for a world seen from above",
                        type="array")
    sensor_angles = Parameter("-1.2 -0.6 0 0.6 1.2", "directions of the range sensors, "
                              "radians relative to the heading (positive to the left)",
                              type="array")
    sensor_range = Parameter(2.0, "the longest distance a range sensor reports, metres")
    time_step = Parameter(None, "seconds simulated per tick; 0 or unset: the model's "
                          "tick_duration", type="number")
    substeps = Parameter(10, "physics steps per tick")

    MOVE = Input("left and right wheel speeds, m/s; unconnected, the robot is not driven",
                 optional=True)

    POSE = Output("the robot's x, y and heading (radians)", size="3")
    VELOCITY = Output("the robot's vx, vy (m/s) and angular velocity (rad/s)", size="3")
    RANGES = Output("distance seen by each range sensor, from the robot's rim, at most "
                    "sensor_range", shape="sensor_angles.size")
    RANGE_POINTS = Output("the end point (x, y) of each sensor ray, one row each",
                          shape="sensor_angles.size, 2")
    COLLISION = Output("1 when the robot touches a wall, an obstacle or an object", size="1")
    OBJECTS = Output("one row per object: x, y, angle, radius (one row of zeros when there "
                     "are no objects)")
    OBJECT_VELOCITIES = Output("one row per object: vx, vy, angular velocity (one row of "
                               "zeros when there are no objects)")
    WALLS = Output("line segments of the arena edges and the obstacles: x0, y0, x1, y1 "
                   "per row")
    MOMENTUM = Output("total linear momentum (px, py) of the robot and the objects",
                      size="2")
    ENERGY = Output("total kinetic energy (translation and rotation) of the robot and the "
                    "objects, J", size="1")

    def configure(self):
        self._pymunk = require("pymunk", "pymunk", extra="physics")

    def _object_rows(self):
        rows = np.asarray(self.objects, np.float64)
        if rows.size == 0:
            return np.zeros((0, 6))
        rows = rows.reshape(-1, rows.shape[-1]) if rows.ndim > 1 else rows.reshape(1, -1)
        if rows.shape[1] < 4:
            raise ValueError("each row of objects needs x, y, radius and mass")
        return np.hstack([rows[:, :6], np.zeros((len(rows), max(0, 6 - rows.shape[1])))])

    def _obstacle_rows(self):
        rows = np.asarray(self.obstacles, np.float64)
        if rows.size == 0:
            return np.zeros((0, 4))
        if rows.size % 4:
            raise ValueError("each row of obstacles needs x0, y0, x1, y1")
        return rows.reshape(-1, 4)

    def set_sizes(self):
        n = len(self._object_rows())
        self.set_output_shape("OBJECTS", (max(n, 1), 4))
        self.set_output_shape("OBJECT_VELOCITIES", (max(n, 1), 3))
        self.set_output_shape("WALLS", (4 + 4 * len(self._obstacle_rows()), 4))

    def init(self):
        if self.MOVE is not None and self.MOVE.size < 2:
            raise ValueError(f"MOVE has {self.MOVE.size} elements; it needs 2")
        self._build()
        self._write()

    def command(self, name, x=0, y=0, value=None):
        if name == "reset":
            self._build()
            self._write()

    # --- the world ----------------------------------------------------------------------
    def _build(self):
        pm = self._pymunk
        space = pm.Space()
        space.gravity = tuple(float(g) for g in (list(self.gravity) + [0, 0])[:2])
        space.damping = float(self.damping)
        space.collision_slop = 0.0005
        space.iterations = 20
        self._space = space
        w, h, t = float(self.width), float(self.height), _WALL_THICKNESS
        walls = [(-t, -t, 0, h + t), (w, -t, w + t, h + t), (0, -t, w, 0), (0, h, w, h + t)]
        segments = [(0, 0, w, 0), (w, 0, w, h), (w, h, 0, h), (0, h, 0, 0)]
        for x0, y0, x1, y1 in self._obstacle_rows():
            x0, x1 = sorted((x0, x1))
            y0, y1 = sorted((y0, y1))
            walls.append((x0, y0, x1, y1))
            segments += [(x0, y0, x1, y0), (x1, y0, x1, y1), (x1, y1, x0, y1), (x0, y1, x0, y0)]
        for x0, y0, x1, y1 in walls:
            box = pm.Poly(space.static_body, [(x0, y0), (x1, y0), (x1, y1), (x0, y1)])
            self._material(box)
            space.add(box)
        self.WALLS[...] = np.array(segments, np.float32)

        r, m = float(self.robot_radius), float(self.robot_mass)
        self._robot = pm.Body(m, pm.moment_for_circle(m, 0, r))
        self._robot.position = (float(self.robot_x), float(self.robot_y))
        self._robot.angle = float(self.robot_heading)
        self._robot_shape = pm.Circle(self._robot, r)
        self._robot_shape.filter = pm.ShapeFilter(group=_ROBOT_GROUP)
        self._material(self._robot_shape)
        space.add(self._robot, self._robot_shape)
        if self.MOVE is not None:
            # The wheels act through two velocity constraints of limited force between the
            # robot and a kinematic control body (so walls and heavy objects can stop it).
            self._control = pm.Body(body_type=pm.Body.KINEMATIC)
            self._control.position = self._robot.position
            pivot = pm.PivotJoint(self._control, self._robot, (0, 0), (0, 0))
            pivot.max_bias = 0
            pivot.max_force = float(self.drive_force)
            gear = pm.GearJoint(self._control, self._robot, 0.0, 1.0)
            gear.error_bias = 0
            gear.max_bias = 0
            gear.max_force = float(self.drive_force) * r
            space.add(self._control, pivot, gear)

        self._bodies = []
        self._radii = []
        for x, y, radius, mass, vx, vy in self._object_rows():
            body = pm.Body(float(mass), pm.moment_for_circle(float(mass), 0, float(radius)))
            body.position = (float(x), float(y))
            body.velocity = (float(vx), float(vy))
            shape = pm.Circle(body, float(radius))
            self._material(shape)
            space.add(body, shape)
            self._bodies.append(body)
            self._radii.append(float(radius))

    def _material(self, shape):
        shape.elasticity = float(self.elasticity)
        shape.friction = float(self.friction)

    def tick(self):
        dt = float(self.time_step) if self.time_step and self.time_step > 0 \
            else float(self.clock.tick_duration)
        n = max(int(self.substeps), 1)
        self._space.damping = float(self.damping)
        for _ in range(n):
            self._drive()
            self._space.step(dt / n)
        self._write()

    def _drive(self):
        if self.MOVE is None:
            return
        left, right = np.clip(np.asarray(self.MOVE, np.float64).reshape(-1)[:2],
                              -self.max_speed, self.max_speed)
        v = 0.5 * (left + right)
        a = self._robot.angle
        self._control.velocity = (v * math.cos(a), v * math.sin(a))
        self._control.angular_velocity = (right - left) / self.wheel_base \
            if self.wheel_base > 0 else 0.0

    # --- outputs ------------------------------------------------------------------------
    def _write(self):
        robot = self._robot
        x, y = robot.position
        a = robot.angle
        self.POSE[...] = (x, y, (a + math.pi) % (2 * math.pi) - math.pi)
        self.VELOCITY[...] = (robot.velocity[0], robot.velocity[1], robot.angular_velocity)
        bodies = [robot] + self._bodies
        masses = np.array([b.mass for b in bodies])
        velocities = np.array([tuple(b.velocity) for b in bodies])
        spins = np.array([b.angular_velocity for b in bodies])
        moments = np.array([b.moment for b in bodies])
        self.MOMENTUM[...] = masses @ velocities
        self.ENERGY[0] = 0.5 * (masses @ (velocities ** 2).sum(axis=1) + moments @ spins ** 2)
        if self._bodies:
            self.OBJECTS[:, 0:2] = [tuple(b.position) for b in self._bodies]
            self.OBJECTS[:, 2] = [b.angle for b in self._bodies]
            self.OBJECTS[:, 3] = self._radii
            self.OBJECT_VELOCITIES[:, 0:2] = velocities[1:]
            self.OBJECT_VELOCITIES[:, 2] = spins[1:]
        else:
            self.OBJECTS.fill(0)
            self.OBJECT_VELOCITIES.fill(0)
        self._sense(x, y, a)
        self.COLLISION[0] = 1.0 if self._space.shape_query(self._robot_shape) else 0.0

    def _sense(self, x, y, a):
        r = float(self.robot_radius)
        reach = max(float(self.sensor_range), 0.0)
        pm_filter = self._pymunk.ShapeFilter(group=_ROBOT_GROUP)
        directions = a + np.asarray(self.sensor_angles, np.float64).reshape(-1)
        for i, d in enumerate(directions):
            ux, uy = math.cos(d), math.sin(d)
            start = (x + r * ux, y + r * uy)
            end = (start[0] + reach * ux, start[1] + reach * uy)
            hit = self._space.segment_query_first(start, end, 0, pm_filter) if reach > 0 \
                else None
            distance = reach * hit.alpha if hit is not None else reach
            self.RANGES[i] = distance
            self.RANGE_POINTS[i] = (start[0] + distance * ux, start[1] + distance * uy)
