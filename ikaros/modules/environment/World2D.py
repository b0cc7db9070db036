"""World2D: a 2-D world seen from above: Ikaros 3's creature among food, aversive objects
and walls, or this project's physics arena (pymunk) with a robot and range sensors."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter, require

from ._creature_world import (OBJECT_COLUMNS, WALL_COLUMNS, CreatureWorld, rows,
                              segment_distance)
from ._physics_world import PhysicsWorld

EDIT_TOOLS = ("EDIT_OBJECT_ENABLE", "EDIT_WALL_ENABLE", "EDIT_COLOR_ENABLE")
NEW_OBJECT_RADIUS = 8.0


class World2D(Module):
    """A 2-D world seen from above, one of two simulations (``simulation``): Ikaros 3's
    ``creature`` world, the default in an Ikaros 3 file, or this project's ``physics``
    arena, the default in an Ikaros 2 file (Ikaros 2 has no World2D).

    **creature** (this project's reading of Ikaros 3's interface; no run of the original
    was compared). A world of world_width × world_height units with a round creature
    (``creature_radius``, starting at creature_x, creature_y, creature_heading; headings in
    radians from +x towards +y) driven by two wheels of ``wheel_radius`` ``wheel_base``
    apart: MOTOR is the (left, right) wheel rotations per tick, each clipped to
    ±``max_motor_rpt``; the wheels travel 2π·wheel_radius times that, so the creature moves
    their mean along an arc and turns (right − left) / wheel_base radians. It goes as far
    along the arc as it can without overlapping a wall, an opaque object or the edge of the
    world (the rest of the turn then happens in place). Objects are the rows of ``food``
    and ``aversive`` (id, x, y, radius, value, red, green, blue, opaque, 8 smell channels);
    walls the rows of ``walls`` (id, x1, y1, x2, y2, red, green, blue, opaque, width,
    solid), a line of that width. Every tick after the motion: CONTACT is (left, right),
    1 where the body touches something solid (a wall, an opaque object, the edge) on that
    side of its heading (straight ahead: both); REWARD is the sum of the positive values of the objects it
    touches or covers, PUNISHMENT that of the negative ones (as a positive number), and
    REINFORCEMENT = REWARD − PUNISHMENT; the two whiskers leave the rim at ±whisker_angle
    (left first) and WHISKERS is 1 − the distance to the first solid thing along each /
    whisker_length (0 when nothing is within reach); ODOUR (2 × 8: left, right) is at the
    whisker roots the sum over the objects of their smell channels times exp(−odour_decay
    × the distance to the object's edge). POSE is (x, y, heading), CREATURE (x, y,
    heading, radius, whisker_length, whisker_angle, the two WHISKERS, REINFORCEMENT).
    OBJECTS has a row per object (id, type 1 food or 2 aversive, x, y, radius, value,
    red, green, blue, opaque, smells) and WALLS a row per wall (id, opaque, x1, y1, x2,
    y2, red, green, blue, solid, width), the tables PlanarArm writes. Editing: the
    EDIT_*_ENABLE outputs are 1 for the ``edit_tool`` chosen (1 objects, 2 walls, 3
    colours; 0 none); the commands ``add_object`` (x, y: food when ``edit_type`` is 0,
    aversive when 1, with radius 8, edit_value, edit_color, edit_opaque and edit_smell),
    ``remove_object`` (the object at x, y), ``add_wall`` (from x, y to the value's two
    numbers, width 2, edit_color, edit_opaque), ``remove_wall`` (the wall nearest x, y
    within 5) and ``set_color`` (the object at x, y takes edit_color) change the ``food``,
    ``aversive`` and ``walls`` matrices; ``reset`` puts the creature back.

    **physics** (this project's). An arena of ``width`` x ``height`` metres (x to the
    right, y up, angles counter-clockwise from the x axis), simulated with the pymunk
    rigid-body engine (the paper's worlds used Box2D). It holds a round robot with two
    wheels, round objects that it can push, and static box obstacles. MOVE gives the
    robot's left and right wheel speeds in m/s (clipped to ``max_speed``): its forward
    speed is their mean and it turns at (right - left) / ``wheel_base`` rad/s, reached with
    at most ``drive_force`` (so walls and heavy objects stop it); unconnected, the robot is
    a free body like the objects. The robot's range sensors cast rays from its rim at
    ``sensor_angles`` (relative to its heading) and report the distance to the nearest
    wall, obstacle or object, or ``sensor_range`` when nothing is closer. Each tick
    advances the world by ``time_step`` seconds (0: the model's tick_duration) in
    ``substeps`` steps. Every shape has the same ``elasticity`` (1 = elastic) and
    ``friction``; ``damping`` is the fraction of their velocity that bodies keep per second
    (1 = none lost, as on ice; floor friction of the top-down view). MOMENTUM and ENERGY
    are the total linear momentum and kinetic energy of the robot and the objects, so that
    losses can be watched. POSE is the robot's x, y and heading, OBJECTS a row per object
    (x, y, angle, radius; one row of zeros without objects), WALLS the arena edges and
    obstacle edges as line segments (x0, y0, x1, y1), for drawing. Needs pymunk (pip
    install 'ikaros[physics]').

    The outputs of the other simulation stay 0."""

    simulation = Parameter("physics", "creature: Ikaros 3's creature world; physics: this "
                           "project's pymunk arena", options="physics,creature",
                           default_v3="creature")
    world_width = Parameter(300.0, "creature: width of the world")
    world_height = Parameter(300.0, "creature: height of the world")
    creature_x = Parameter(150.0, "creature: starting x")
    creature_y = Parameter(150.0, "creature: starting y")
    creature_heading = Parameter(0.0, "creature: starting heading, radians from +x")
    creature_radius = Parameter(4.0, "creature: radius of its body", range=(0, None))
    wheel_radius = Parameter(1.0, "creature: radius of its wheels")
    max_motor_rpt = Parameter(0.25, "creature: largest wheel rotations per tick")
    whisker_length = Parameter(10.0, "creature: length of the whiskers beyond the rim")
    whisker_angle = Parameter(0.7853981633974483, "creature: angle of each whisker from "
                              "the heading")
    odour_decay = Parameter(0.01, "creature: odour falls as exp(-odour_decay × distance)")
    edit_tool = Parameter("0", "creature: the editing tool: 0 none, 1 objects, 2 walls, 3 "
                          "colours", type="matrix")
    edit_type = Parameter("0", "creature: what add_object adds: 0 food, 1 aversive",
                          type="matrix")
    edit_value = Parameter("0", "creature: the value of an added object", type="matrix")
    edit_opaque = Parameter("1", "creature: whether an added object or wall is solid",
                            type="matrix")
    edit_smell = Parameter("0,0,0,0,0,0,0,0", "creature: the smell channels of an added "
                           "object", type="matrix")
    edit_color = Parameter("0,0,0", "creature: the colour of an added or recoloured thing",
                           type="matrix")
    food = Parameter("1,70,70,5,1,0.20,0.70,0.25,0,1,0,0,0,0,0,0,0; "
                     "2,225,215,7,1,0.95,0.70,0.15,0,0,1,0,0,0,0,0,0",
                     "creature: food, a row each: id, x, y, radius, value, red, green, blue, "
                     "opaque, 8 smells", type="matrix")
    aversive = Parameter("3,210,85,10,-1,0.85,0.20,0.18,1,0,0,0,0,0,0,0,1; "
                         "4,112,120,12,-1,0.48,0.48,0.50,1,0,0,0,0,0,0,0,1; "
                         "5,172,160,16,-1,0.48,0.48,0.50,1,0,0,0,0,0,0,0,1; "
                         "6,95,220,14,-1,0.48,0.48,0.50,1,0,0,0,0,0,0,0,1; "
                         "7,245,150,11,-1,0.48,0.48,0.50,1,0,0,0,0,0,0,0,1",
                         "creature: aversive objects, rows as food", type="matrix")
    walls = Parameter("8,50,45,250,45,0.18,0.18,0.18,1,2,1; "
                      "9,50,255,250,255,0.18,0.18,0.18,1,2,1; "
                      "10,50,45,50,255,0.18,0.18,0.18,1,2,1; "
                      "11,250,45,250,255,0.18,0.18,0.18,1,2,1; "
                      "12,125,75,125,185,0.18,0.18,0.18,1,3,1; "
                      "13,175,115,230,115,0.18,0.18,0.18,1,3,1",
                      "creature: walls, a row each: id, x1, y1, x2, y2, red, green, blue, "
                      "opaque, width, solid", type="matrix")
    width = Parameter(4.0, "physics: width of the arena (x), metres")
    height = Parameter(3.0, "height of the arena (y), metres")
    robot_x = Parameter(1.0, "the robot's starting x")
    robot_y = Parameter(1.5, "the robot's starting y")
    robot_heading = Parameter(0.0, "the robot's starting heading, radians counter-clockwise "
                              "from the x axis")
    robot_radius = Parameter(0.15, "radius of the robot's round body, metres")
    robot_mass = Parameter(5.0, "mass of the robot, kg")
    wheel_base = Parameter(0.3, "distance between the wheels: metres (physics), units "
                           "(creature)", default_v3=6.0)
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


    MOTOR = Input("creature: left and right wheel rotations per tick", optional=True)
    MOVE = Input("physics: left and right wheel speeds, m/s; unconnected, the robot is not "
                 "driven", optional=True)

    POSE = Output("x, y and heading (radians) of the creature or robot", size="3")
    OBJECTS = Output("the objects, a row each (see the description)")
    WALLS = Output("the walls, a row each (see the description)")
    CREATURE = Output("creature: x, y, heading, radius, whisker length and angle, the two "
                      "whiskers, reinforcement", size="9")
    CONTACT = Output("creature: the body touches something solid on its left, right",
                     size="2")
    WHISKERS = Output("creature: left and right whisker, 1 - distance / length", size="2")
    ODOUR = Output("creature: the smell at the left and right whisker roots, 8 channels",
                   size="2,8")
    REINFORCEMENT = Output("creature: REWARD - PUNISHMENT", size="1")
    REWARD = Output("creature: the positive values of the objects touched", size="1")
    PUNISHMENT = Output("creature: minus the negative values of the objects touched",
                        size="1")
    EDIT_OBJECT_ENABLE = Output("creature: 1 when edit_tool is 1 (objects)", size="1")
    EDIT_WALL_ENABLE = Output("creature: 1 when edit_tool is 2 (walls)", size="1")
    EDIT_COLOR_ENABLE = Output("creature: 1 when edit_tool is 3 (colours)", size="1")
    VELOCITY = Output("the robot's vx, vy (m/s) and angular velocity (rad/s)", size="3")
    RANGES = Output("distance seen by each range sensor, from the robot's rim, at most "
                    "sensor_range", shape="sensor_angles.size")
    RANGE_POINTS = Output("the end point (x, y) of each sensor ray, one row each",
                          shape="sensor_angles.size, 2")
    COLLISION = Output("1 when the robot touches a wall, an obstacle or an object", size="1")
    OBJECT_VELOCITIES = Output("one row per object: vx, vy, angular velocity (one row of "
                               "zeros when there are no objects)")
    MOMENTUM = Output("total linear momentum (px, py) of the robot and the objects",
                      size="2")
    ENERGY = Output("total kinetic energy (translation and rotation) of the robot and the "
                    "objects, J", size="1")

    def configure(self):
        self._pymunk = require("pymunk", "pymunk", extra="physics") \
            if self.simulation == "physics" else None

    def set_sizes(self):
        if self.simulation == "creature":
            n = len(rows(self.food, OBJECT_COLUMNS, "food")) + \
                len(rows(self.aversive, OBJECT_COLUMNS, "aversive"))
            self.set_output_shape("OBJECTS", (max(n, 1), OBJECT_COLUMNS + 1))
            self.set_output_shape("WALLS", (max(len(rows(self.walls, WALL_COLUMNS,
                                                         "walls")), 1), WALL_COLUMNS))
            self.set_output_shape("OBJECT_VELOCITIES", (1, 3))
            return
        n = len(_physics_rows(self.objects, 4))
        self.set_output_shape("OBJECTS", (max(n, 1), 4))
        self.set_output_shape("OBJECT_VELOCITIES", (max(n, 1), 3))
        self.set_output_shape("WALLS", (4 + 4 * len(_physics_rows(self.obstacles, 4)), 4))

    def init(self):
        self._world = self._physics = None
        if self.simulation == "creature":
            if self.MOTOR is not None and self.MOTOR.size < 2:
                raise ValueError(f"MOTOR has {self.MOTOR.size} elements; it needs 2")
            self._world = CreatureWorld(self)
            self._write_creature()
            return
        if self.MOVE is not None and self.MOVE.size < 2:
            raise ValueError(f"MOVE has {self.MOVE.size} elements; it needs 2")
        self._physics = PhysicsWorld(self, self._pymunk)

    def tick(self):
        if self._world is None:
            self._physics.step()
            return
        self._world.move(self.MOTOR)
        self._world.sense()
        self._write_creature()

    def command(self, name, x=0, y=0, value=None):
        if name == "reset":
            if self._world is None:
                self._physics = PhysicsWorld(self, self._pymunk)
            else:
                self._world.reset()
                self._write_creature()
            return
        if self._world is not None and name in _EDITS:
            _EDITS[name](self, float(x), float(y), value)
            self._world = _rebuilt(self, self._world)
            self._write_creature()

    # --- creature outputs ---------------------------------------------------------------
    def _write_creature(self):
        w = self._world
        self.POSE[...] = (w.x, w.y, w.heading)
        self.CONTACT[...] = w.contact
        self.WHISKERS[...] = w.whiskers
        self.ODOUR[...] = w.odour
        self.REWARD[0], self.PUNISHMENT[0] = w.reward, w.punishment
        self.REINFORCEMENT[0] = w.reward - w.punishment
        self.CREATURE[...] = (w.x, w.y, w.heading, self.creature_radius, self.whisker_length,
                              self.whisker_angle, w.whiskers[0], w.whiskers[1],
                              w.reward - w.punishment)
        objects, walls = self._fitting("OBJECTS", w.objects), self._fitting("WALLS", w.walls)
        self.OBJECTS.fill(0)
        n = len(objects)
        self.OBJECTS[:n, 0], self.OBJECTS[:n, 1] = objects[:, 0], w.kinds[:n]
        self.OBJECTS[:n, 2:] = objects[:, 1:]
        self.WALLS.fill(0)
        self.WALLS[:len(walls)] = walls[:, [0, 8, 1, 2, 3, 4, 5, 6, 7, 10, 9]]
        tool = int(np.ravel(self.edit_tool)[0]) if np.size(self.edit_tool) else 0
        for k, name in enumerate(EDIT_TOOLS):
            getattr(self, name)[0] = 1.0 if tool == k + 1 else 0.0


    def _fitting(self, output, table):
        """The rows of ``table`` that fit in an output sized when the model was built (rows
        added by editing beyond it are left out, with a warning)."""
        room = getattr(self, output).shape[0]
        if len(table) > room:
            self.warning(f"{output} has room for {room} rows (its size is fixed when the "
                         f"model is built): the last {len(table) - room} are not shown")
        return table[:room]


def _physics_rows(value, columns):
    data = np.asarray(value, np.float64)
    return np.zeros((0, columns)) if data.size == 0 else data.reshape(-1, data.shape[-1]) \
        if data.ndim > 1 else data.reshape(1, -1)


def _rebuilt(m, old):
    """A new world from the edited matrices, with the creature where it was."""
    world = CreatureWorld(m)
    world.x, world.y, world.heading = old.x, old.y, old.heading
    world.sense()
    return world


def _object_at(m, x, y):
    """(matrix name, row) of the object at (x, y), or None."""
    for name in ("food", "aversive"):
        table = rows(getattr(m, name), OBJECT_COLUMNS, name)
        for k, o in enumerate(table):
            if math.hypot(x - o[1], y - o[2]) <= o[3]:
                return name, k
    return None


def _next_id(m):
    ids = [rows(getattr(m, n), c, n)[:, 0] for n, c in (
        ("food", OBJECT_COLUMNS), ("aversive", OBJECT_COLUMNS), ("walls", WALL_COLUMNS))]
    ids = np.concatenate(ids)
    return float(ids.max() + 1) if ids.size else 1.0


def _add_object(m, x, y, value):
    name = "aversive" if int(np.ravel(m.edit_type)[0]) == 1 else "food"
    smell = (list(np.ravel(m.edit_smell)) + [0.0] * 8)[:8]
    colour = (list(np.ravel(m.edit_color)) + [0.0] * 3)[:3]
    row = [_next_id(m), x, y, NEW_OBJECT_RADIUS, float(np.ravel(m.edit_value)[0]), *colour,
           float(np.ravel(m.edit_opaque)[0]), *smell]
    setattr(m, name, np.vstack([rows(getattr(m, name), OBJECT_COLUMNS, name), row]))


def _remove_object(m, x, y, value):
    found = _object_at(m, x, y)
    if found:
        name, k = found
        setattr(m, name, np.delete(rows(getattr(m, name), OBJECT_COLUMNS, name), k, axis=0))


def _set_color(m, x, y, value):
    found = _object_at(m, x, y)
    if found:
        name, k = found
        table = rows(getattr(m, name), OBJECT_COLUMNS, name)
        table[k, 5:8] = (list(np.ravel(m.edit_color)) + [0.0] * 3)[:3]
        setattr(m, name, table)


def _add_wall(m, x, y, value):
    end = np.ravel(np.asarray(value if value is not None else [x, y], np.float64))
    if end.size < 2:
        raise ValueError("add_wall needs the wall's other end as its value (x2, y2)")
    colour = (list(np.ravel(m.edit_color)) + [0.0] * 3)[:3]
    row = [_next_id(m), x, y, end[0], end[1], *colour, float(np.ravel(m.edit_opaque)[0]),
           2.0, 1.0]
    m.walls = np.vstack([rows(m.walls, WALL_COLUMNS, "walls"), row])


def _remove_wall(m, x, y, value):
    table = rows(m.walls, WALL_COLUMNS, "walls")
    if len(table):
        point = np.array([x, y])
        distances = [segment_distance(point, w[1:3], w[3:5]) for w in table]
        k = int(np.argmin(distances))
        if distances[k] <= 5:
            m.walls = np.delete(table, k, axis=0)


_EDITS = {"add_object": _add_object, "remove_object": _remove_object,
          "set_color": _set_color, "add_wall": _add_wall, "remove_wall": _remove_wall}
