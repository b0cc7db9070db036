"""GLRobotSimulator: a mobile builder robot with an arm that picks up and places blocks."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._gl_ranges import range_map, wall_points

MAX_ROWS = 50
EMPTY = -99999.0                 # Ikaros 2's value for no object and no target


def _empty_table(whole_rows: bool) -> np.ndarray:
    """BLOCKS or LANDMARKS without objects: -99999 in every place, or as Ikaros 2 writes
    them, in the first 100 values (row by row) and the first two places of every row, 0
    elsewhere."""
    if whole_rows:
        return np.full((MAX_ROWS, 6), EMPTY)
    table = np.zeros((MAX_ROWS, 6))
    table.reshape(-1)[:2 * MAX_ROWS] = EMPTY
    table[:, :2] = EMPTY
    return table
BLOCK, LANDMARK = 1, 2
SHOULDER_HEIGHT = 150.0          # mm above the floor
ROBOT_HEIGHT = 120.0
REACH_TICKS, GRASP_TICKS = 10, 5
CHARGE_DISTANCE = 100.0          # mm from the charging station
CHARGE_RATE = 0.01               # battery per tick while charging
# indices of the one-hot phase outputs
IDLE, TURNING, DRIVING, ARRIVED, FAILED = range(5)
REACHING, GRASPING, LIFTING, DONE = range(1, 5)


def _rising(value, previous) -> bool:
    return value is not None and value.reshape(-1)[0] > 0 and previous <= 0


def _turned(heading: float, turn: float) -> float:
    """heading + turn in single precision, brought into -pi .. pi as Ikaros 2 does."""
    new = float(np.float32(heading) + np.float32(turn))
    if new > math.pi:
        new -= 2 * math.pi
    elif new < -math.pi:
        new += 2 * math.pi
    return float(np.float32(new))


def _first(value, default=0.0) -> float:
    return float(value.reshape(-1)[0]) if value is not None and value.size else default


def _segment_transform(a, b, thickness):
    """A row-major 4x4 transform that stretches a unit box from point a to point b."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    axis = b - a
    length = float(np.linalg.norm(axis)) or 1e-9
    x = axis / length
    helper = np.array([0.0, 0.0, 1.0]) if abs(x[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    y = np.cross(helper, x)
    y /= np.linalg.norm(y)
    z = np.cross(x, y)
    m = np.eye(4)
    m[:3, 0], m[:3, 1], m[:3, 2] = x * length, y * thickness, z * thickness
    m[:3, 3] = (a + b) / 2
    return m


def _placed_transform(position, heading, size):
    """A row-major 4x4 transform: scale ``size`` (x, y, z), turned by heading, at position."""
    c, s = math.cos(heading), math.sin(heading)
    m = np.eye(4)
    m[:3, :3] = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]) @ np.diag(size)
    m[:3, 3] = position
    return m


class GLRobotSimulator(Module):
    """A simulated builder robot (after the Goal-Leaders robot of Ikaros 2) in a rectangular
    arena seen from above (``arena_size``; 1700 x 1200 mm as in Ikaros 2), in millimetres:
    x, y on the floor, z up, headings in radians counter-clockwise from the x axis, kept in
    -pi .. pi. The robot starts at ``start`` ((100, 100) facing along x, as in Ikaros 2).
    OBJECTS_IN gives the objects on the first tick, one row of 6 values each: kind (1 block,
    2 landmark; any other value is no object), id, x, y, z, colour; values after the last
    whole row are not objects (a warning). OBJECTS_OUT is OBJECTS_IN with the objects as
    they are now. BLOCKS and LANDMARKS list them (id, x, y, z, colour, held), up to 50 rows;
    without objects they hold -99999 in their first 100 values and in the first two places
    of every row, 0 elsewhere, as Ikaros 2 writes them (a defect of the original:
    ``empty_rows="whole"`` puts -99999 in every place of an empty row).

    DIRECT_CONTROL (dx, dy, -, dheading) drives the robot while any of its values is not 0:
    the heading turns by dheading at once, and the robot moves by (dx, dy) after the
    outputs are written (the move shows on the next tick), each coordinate kept
    ``robot_radius`` from the walls, in single precision, as the golden files of Ikaros 2
    show; what its third value does they do not show, and it is not used here. While it
    drives, a LOCOMOTION_TRIGGER is not taken.

    Locomotion: LOCOMOTION_TRIGGER rising above 0 starts a trip to GOAL_LOCATION (x, y):
    the robot turns at ``rotation_speed`` rad/tick, then drives at ``locomotion_speed``
    mm/tick times SPEED (default 1). It stops with LOCOMOTION_ERROR when the goal is
    outside the arena, when it would run into a landmark, a block on the floor or a wall
    (its radius is ``robot_radius``) or when the battery is empty.

    The arm (two links of ``arm_length``/2 from a shoulder 150 mm up, plus a gripper) reaches
    ``arm_length`` around the robot. PICK_OBJECT_TRIGGER rising above 0 picks the block
    PICK_OBJECT_ID, or when that is 0 or unconnected the block nearest to
    PICK_OBJECT_SPATIAL_ATTENTION (x, y) within one block size; the block must be in reach,
    free (nothing on top) and the gripper empty, otherwise PICK_ERROR (as in Ikaros 2, where
    a trigger of 0.1 with no such block gives it). PLACE_OBJECT_TRIGGER rising above 0 puts
    the held block at PLACE_OBJECT_LOCATION (x, y), in reach, on top of whatever is stacked
    there (``auto_stack``: a location within one block of a block snaps onto it). Each takes
    reaching (10 ticks), grasping or lowering (5), and lifting or releasing (10). MOVE_BLOCK
    (id, x, y) puts a block there at once (on top of a stack), for experiments.

    The battery (BATTERY_LEVEL, 0..1) loses ``battery_decay`` per tick while a trip or an
    arm action runs (nothing while the robot is idle or driven by DIRECT_CONTROL, as in the
    golden files); CHARGE_BATTERIES above 0.5 charges it by 0.01 per tick when the robot is
    within 100 mm of ``charging_station`` (otherwise CHARGE_ERROR).

    LOCOMOTION_PHASE is one-hot (idle, turning, driving, arrived, failed); PICK_PHASE and
    PLACE_PHASE have a 1 at the running step (reaching 1, grasping / lowering 2, lifting /
    releasing 3, done 4) and are all 0 while idle, CHARGE_PHASE is (0, 1) while charging
    and (0, 0) otherwise (idle as the golden files show); an error output is 1 from a
    failure until the next trigger of the same action. ROBOT_LOCATION is (x, y, id of the
    held block or 0, heading): the golden files show (x, y, 0, heading) with nothing held.
    SPEED_OUT is the first value of SPEED (1 when unconnected), as the golden files show.
    TARGET is the goal of the running action (x, y, z, then 1 locomotion, 2 pick, 3 place),
    -99999 in every place while none runs. VIEW_FIELD is the point ``view_distance`` ahead of
    the robot (450 mm in Ikaros 2), and BLOCKS_IN_VIEW the blocks within ``view_radius`` of
    it (empty rows 0).

    RANGE_MAP is Ikaros 2's: 32 sectors around the robot, running clockwise from the one
    just counter-clockwise of the heading (sector 16), each the distance to the nearest
    point of whole millimetres on the walls in it, ``range_limit`` (1700) where none is
    nearer (the rule is in ``_gl_ranges``); it reproduces the golden files of Ikaros 2 to
    the last digit. The original truncates the sector's quotient towards 0, which makes the
    sector behind the robot wider than the others; ``range_sectors="even"`` gives 32 equal
    sectors. Blocks and landmarks on the floor count at the distance of their edge
    in the sector of their centre, and RANGE_COLOR is the colour of the object a sector
    holds (0: a wall or nothing); the golden files, which have no objects, do not show how
    the original counts them. TRANSFORMS draws the scene in the web UI's 3-D view
    (canvas3d, metres): rows of row-major 4x4 transforms of unit shapes: the body
    (cylinder), the upper arm, the forearm and the gripper (boxes), the charging station,
    and one row per whole row of OBJECTS_IN (boxes for blocks, cylinders for landmarks; an
    empty row is scaled to nothing).

    What the golden files of Ikaros 2 show (a robot driven by DIRECT_CONTROL, a pick that
    fails, nothing placed) is followed; trips, the arm's motion and timings, collisions,
    charging and the row format of OBJECTS_IN are this implementation's. On the golden
    files' other case (every input a changing 4-element vector) the original stops after
    tick 0, its output file cut short inside that record; this class runs on."""

    locomotion_speed = Parameter(10.0, "driving speed, mm per tick")
    rotation_speed = Parameter(0.1, "turning speed, radians per tick")
    arm_length = Parameter(300.0, "reach of the arm from the robot's centre, mm")
    charging_station = Parameter("1475 225", "position (x, y) of the charging station, mm",
                                 type="array")
    view_radius = Parameter(300.0, "radius of the disc the robot sees, mm")
    battery_decay = Parameter(0.0001, "battery used per tick (twice that while moving)")
    auto_stack = Parameter(False, "a block placed within one block size of another is "
                           "stacked on it")
    arena_size = Parameter("1700 1200", "width and depth of the arena, mm", type="array")
    start = Parameter("100 100 0", "the robot's start x, y (mm) and heading (rad)",
                      type="array")
    view_distance = Parameter(450.0, "distance of VIEW_FIELD ahead of the robot, mm")
    range_limit = Parameter(1700.0, "RANGE_MAP where nothing is nearer, mm")
    empty_rows = Parameter("ikaros2", "how BLOCKS and LANDMARKS mark rows without an object: "
                           "ikaros2 (-99999 in the first 100 values and the first two places "
                           "of each row, as the original writes them) or whole (-99999 in "
                           "every place)", options="ikaros2,whole")
    range_sectors = Parameter("ikaros2", "RANGE_MAP's sectors: ikaros2 (the original's, the "
                              "one behind the robot wider) or even (all 2 pi / 32)",
                              options="ikaros2,even")
    robot_radius = Parameter(100.0, "radius of the robot's round body, mm")
    block_size = Parameter(50.0, "edge of a block (and diameter of a landmark), mm")

    OBJECTS_IN = Input("the objects: kind (1 block, 2 landmark), id, x, y, z, colour per row")
    MOVE_BLOCK = Input("id, x, y: puts that block there at once", optional=True)
    PICK_OBJECT_SPATIAL_ATTENTION = Input("x, y: picks the block nearest to it (when "
                                          "PICK_OBJECT_ID is 0)", optional=True)
    GOAL_LOCATION = Input("x, y to drive to", optional=True)
    SPEED = Input("speed factor of locomotion (default 1)", optional=True)
    LOCOMOTION_TRIGGER = Input("a rising edge (above 0.5) starts driving to GOAL_LOCATION",
                               optional=True)
    PICK_OBJECT_ID = Input("the id of the block to pick (0: use the spatial attention)",
                           optional=True)
    PICK_OBJECT_TRIGGER = Input("a rising edge starts picking", optional=True)
    PLACE_OBJECT_LOCATION = Input("x, y where the held block is placed", optional=True)
    PLACE_OBJECT_TRIGGER = Input("a rising edge starts placing", optional=True)
    CHARGE_BATTERIES = Input("above 0.5: charge at the charging station", optional=True)
    DIRECT_CONTROL = Input("dx, dy (mm/tick), unused, dheading (rad/tick), used while not "
                           "all 0", optional=True)

    OBJECTS_OUT = Output("the objects as they are now, rows as OBJECTS_IN",
                         shape="OBJECTS_IN.shape")
    BLOCKS = Output("the blocks: id, x, y, z, colour, held (1); -99999 in empty rows",
                    size_x="6", size_y="50")
    LANDMARKS = Output("the landmarks: id, x, y, z, colour, 0; -99999 in empty rows",
                       size_x="6", size_y="50")
    CHARGING_STATION = Output("x, y of the charging station", size="2")
    VIEW_FIELD = Output("centre x, y of the disc the robot sees", size="2")
    TARGET = Output("x, y, z of the running action's goal, and the action (1 locomotion, 2 "
                    "pick, 3 place); -99999 while none runs", size="4")
    RANGE_MAP = Output("distance to the nearest wall or object in 32 sectors, mm",
                       size="32")
    RANGE_COLOR = Output("colour of what each range ray hits (0: wall or nothing)", size="32")
    BLOCKS_IN_VIEW = Output("the blocks in the view field, rows as BLOCKS", size_x="6",
                            size_y="50")
    ROBOT_LOCATION = Output("x, y of the robot, the id of the held block (0: none), heading",
                            size="4")
    SPEED_OUT = Output("the speed factor SPEED (1 when unconnected)", size="1")
    BATTERY_LEVEL = Output("the battery, 0..1", size="1")
    LOCOMOTION_PHASE = Output("one-hot: idle, turning, driving, arrived, failed", size="5")
    PICK_PHASE = Output("1 at the running step: reaching 1, grasping 2, lifting 3, done 4; "
                        "all 0 while idle", size="5")
    PLACE_PHASE = Output("1 at the running step: reaching 1, lowering 2, releasing 3, done 4; "
                         "all 0 while idle", size="5")
    CHARGE_PHASE = Output("(0, 1) while charging, (0, 0) otherwise", size="2")
    LOCOMOTION_ERROR = Output("1 when the last trip failed", size="1")
    PICK_ERROR = Output("1 when the last pick failed", size="1")
    PLACE_ERROR = Output("1 when the last placing failed", size="1")
    CHARGE_ERROR = Output("1 when charging away from the station", size="1")
    TRANSFORMS = Output("the scene for the 3-D view: 4x4 transforms (metres), one row each")

    def set_sizes(self):
        shape = self.input_shape("OBJECTS_IN")
        if shape is not None:
            rows = int(np.prod(shape)) // 6 if len(shape) else 0
            self.set_output_shape("TRANSFORMS", (5 + rows, 16))

    def init(self):
        if self.OBJECTS_IN.size % 6:
            self.warning(f"OBJECTS_IN has {self.OBJECTS_IN.size} values, not whole rows of 6 "
                         "(kind, id, x, y, z, colour); the last "
                         f"{self.OBJECTS_IN.size % 6} are not objects")
        self._objects = np.zeros((self.OBJECTS_IN.size // 6, 6))
        self._loaded = False
        for name, count in (("arena_size", 2), ("start", 3), ("charging_station", 2)):
            if getattr(self, name).size != count:
                raise ValueError(f"{name} needs {count} values")
        x, y, heading = (float(v) for v in self.start)
        self._pose = np.array([x, y, math.remainder(heading, 2 * math.pi)])
        self._walls = wall_points(*self.arena_size)
        self._move = None                                 # DIRECT_CONTROL's (dx, dy)
        self._held = -1                                   # row index of the held block
        self._battery = 1.0
        self._previous = {}
        self._locomotion = IDLE
        self._goal = None
        self._arm = None                                  # [action, phase, ticks, target]
        self._arm_phase = {"pick": IDLE, "place": IDLE}
        self._hand = self._rest_hand()
        self._errors = {"LOCOMOTION_ERROR": 0.0, "PICK_ERROR": 0.0, "PLACE_ERROR": 0.0,
                        "CHARGE_ERROR": 0.0}
        self._charging = False
        self._write()

    # --- inputs ----------------------------------------------------------------------------

    def _edge(self, name) -> bool:
        value = getattr(self, name)
        previous = self._previous.get(name, 0.0)
        self._previous[name] = _first(value)
        return _rising(value, previous)

    def _load_objects(self):
        """The objects as OBJECTS_IN gives them on the first tick."""
        rows = self.OBJECTS_IN.size // 6
        objects = np.asarray(self.OBJECTS_IN, np.float64).reshape(-1)[:rows * 6]
        objects = objects.reshape(rows, 6).copy()
        self.OBJECTS_OUT.reshape(-1)[...] = self.OBJECTS_IN.reshape(-1)
        for kind, label in ((BLOCK, "blocks"), (LANDMARK, "landmarks")):
            if np.count_nonzero(objects[:, 0] == kind) > MAX_ROWS:
                self.fatal_error(f"OBJECTS_IN has more than {MAX_ROWS} {label}")
        self._objects = objects
        self._loaded = True

    def tick(self):
        if not self._loaded:
            self._load_objects()
        moving = False
        if self.MOVE_BLOCK is not None and self.MOVE_BLOCK.size >= 3 and self.MOVE_BLOCK.flat[0]:
            block_id, x, y = (float(v) for v in self.MOVE_BLOCK.reshape(-1)[:3])
            row = self._block_row(block_id)
            if row is not None and row != self._held:
                self._put(row, x, y)
        direct = self.DIRECT_CONTROL
        driven = direct is not None and bool(np.any(direct != 0))
        if self._edge("LOCOMOTION_TRIGGER") and not driven:
            self._start_trip()
        if self._edge("PICK_OBJECT_TRIGGER"):
            self._start_pick()
        if self._edge("PLACE_OBJECT_TRIGGER"):
            self._start_place()
        if driven:
            values = np.zeros(4)
            given = direct.reshape(-1)[:4]
            values[:given.size] = given
            self._pose[2] = _turned(self._pose[2], values[3])
            self._move = values[:2]
        elif self._locomotion in (TURNING, DRIVING):
            moving = self._travel()
        arm_moving = self._move_arm()
        self._charge()
        if moving or arm_moving:
            self._battery = max(0.0, self._battery - self.battery_decay)
        self._write()
        if self._move is not None:
            self._step_directly(*self._move)
            self._move = None

    def _step_directly(self, dx: float, dy: float):
        """DIRECT_CONTROL's move: each coordinate kept robot_radius from the walls; no move
        into an object."""
        width, depth = (float(v) for v in self.arena_size)
        r = self.robot_radius
        x = min(max(float(np.float32(self._pose[0]) + np.float32(dx)), r), width - r)
        y = min(max(float(np.float32(self._pose[1]) + np.float32(dy)), r), depth - r)
        if not self._collides(x, y):
            self._pose[:2] = x, y

    # --- locomotion --------------------------------------------------------------------------

    def _start_trip(self):
        self._errors["LOCOMOTION_ERROR"] = 0.0
        goal = self.GOAL_LOCATION
        width, depth = (float(v) for v in self.arena_size)
        r = self.robot_radius
        if goal is None or goal.size < 2:
            return self._trip_failed()
        gx, gy = (float(v) for v in goal.reshape(-1)[:2])
        if not (r <= gx <= width - r and r <= gy <= depth - r):
            return self._trip_failed()
        self._goal = np.array([gx, gy])
        self._locomotion = TURNING

    def _trip_failed(self):
        self._locomotion = FAILED
        self._goal = None
        self._errors["LOCOMOTION_ERROR"] = 1.0

    def _travel(self) -> bool:
        if self._battery <= 0:
            self._trip_failed()
            return False
        x, y, heading = self._pose
        dx, dy = self._goal - (x, y)
        distance = math.hypot(dx, dy)
        if self._locomotion == TURNING:
            if distance < 1e-9:
                self._locomotion = ARRIVED
                return False
            turn = (math.atan2(dy, dx) - heading + math.pi) % (2 * math.pi) - math.pi
            step = max(-self.rotation_speed, min(self.rotation_speed, turn))
            self._pose[2] = math.remainder(heading + step, 2 * math.pi)
            if abs(turn) <= self.rotation_speed:
                self._locomotion = DRIVING
            return True
        speed = self.locomotion_speed * (_first(self.SPEED, 1.0) if self.SPEED is not None else 1.0)
        step = min(speed, distance)
        if not self._drive(step):
            self._trip_failed()
            return False
        if step >= distance - 1e-9:
            self._pose[:2] = self._goal         # no rounding left over
            self._locomotion = ARRIVED
        return True

    def _drive(self, forward: float) -> bool:
        """Move forward (mm); False (and no move) when blocked."""
        if self._battery <= 0:
            return False
        x, y, heading = self._pose
        nx, ny = x + forward * math.cos(heading), y + forward * math.sin(heading)
        if forward and self._collides(nx, ny):
            return False
        self._pose[:2] = nx, ny
        return True

    def _collides(self, x, y) -> bool:
        width, depth = (float(v) for v in self.arena_size)
        r = self.robot_radius
        if not (r - 1e-6 <= x <= width - r + 1e-6 and r - 1e-6 <= y <= depth - r + 1e-6):
            return True
        for i, (kind, _, ox, oy, _, _) in enumerate(self._objects):
            if kind in (BLOCK, LANDMARK) and i != self._held and \
                    math.hypot(ox - x, oy - y) < r + self.block_size / 2:
                return True
        return False

    # --- the arm -------------------------------------------------------------------------------

    def _shoulder(self):
        return np.array([self._pose[0], self._pose[1], SHOULDER_HEIGHT])

    def _rest_hand(self):
        x, y, heading = self._pose
        reach = 0.5 * self.arm_length
        return np.array([x + reach * math.cos(heading), y + reach * math.sin(heading),
                         SHOULDER_HEIGHT + 50.0])

    def _in_reach(self, x, y) -> bool:
        return math.hypot(x - self._pose[0], y - self._pose[1]) <= self.arm_length

    def _block_row(self, block_id):
        rows = np.flatnonzero((self._objects[:, 0] == BLOCK) & (self._objects[:, 1] == block_id))
        return int(rows[0]) if rows.size else None

    def _stack_top(self, x, y, ignore=-1) -> float:
        """Height of the top of the blocks stacked at (x, y) (0 on the floor)."""
        top = 0.0
        for i, (kind, _, bx, by, bz, _) in enumerate(self._objects):
            if kind == BLOCK and i != ignore and \
                    max(abs(bx - x), abs(by - y)) < self.block_size * 0.99:
                top = max(top, bz + self.block_size)
        return top

    def _put(self, row, x, y):
        self._objects[row, 2:5] = x, y, self._stack_top(x, y, ignore=row)

    def _start_pick(self):
        self._errors["PICK_ERROR"] = 0.0
        self._arm_phase["pick"] = IDLE
        row = None
        wanted = _first(self.PICK_OBJECT_ID) if self.PICK_OBJECT_ID is not None else 0.0
        if wanted:
            row = self._block_row(wanted)
        elif self.PICK_OBJECT_SPATIAL_ATTENTION is not None and \
                self.PICK_OBJECT_SPATIAL_ATTENTION.size >= 2:
            ax, ay = (float(v) for v in self.PICK_OBJECT_SPATIAL_ATTENTION.reshape(-1)[:2])
            blocks = np.flatnonzero(self._objects[:, 0] == BLOCK)
            if blocks.size:
                d = np.hypot(self._objects[blocks, 2] - ax, self._objects[blocks, 3] - ay)
                nearest = int(np.argmin(d))
                if d[nearest] <= self.block_size:
                    row = int(blocks[nearest])
        ok = row is not None and self._held < 0 and self._arm is None and self._battery > 0
        if ok:
            _, _, bx, by, bz, _ = self._objects[row]
            ok = self._in_reach(bx, by) and self._stack_top(bx, by, ignore=row) <= bz + 1e-6
        if not ok:
            self._errors["PICK_ERROR"] = 1.0
            return
        self._arm = ["pick", REACHING, 0, row]

    def _start_place(self):
        self._errors["PLACE_ERROR"] = 0.0
        self._arm_phase["place"] = IDLE
        where = self.PLACE_OBJECT_LOCATION
        ok = where is not None and where.size >= 2 and self._held >= 0 and self._arm is None \
            and self._battery > 0
        if ok:
            x, y = (float(v) for v in where.reshape(-1)[:2])
            if self.auto_stack:
                for i, (kind, _, bx, by, _, _) in enumerate(self._objects):
                    if kind == BLOCK and i != self._held and \
                            math.hypot(bx - x, by - y) < self.block_size:
                        x, y = bx, by
                        break
            ok = self._in_reach(x, y) and not self._on_robot(x, y)
        if not ok:
            self._errors["PLACE_ERROR"] = 1.0
            return
        self._arm = ["place", REACHING, 0, np.array([x, y])]

    def _on_robot(self, x, y) -> bool:
        return math.hypot(x - self._pose[0], y - self._pose[1]) < self.robot_radius + \
            self.block_size / 2

    def _arm_goal(self):
        action, phase, _, target = self._arm
        if action == "pick":
            bx, by, bz = self._objects[target, 2:5]
            grip = np.array([bx, by, bz + self.block_size])
        else:
            x, y = target
            grip = np.array([x, y, self._stack_top(x, y, ignore=self._held) + self.block_size])
        above = grip + [0.0, 0.0, 60.0]
        return above, grip

    def _move_arm(self) -> bool:
        rest = self._rest_hand()
        if self._arm is None:
            self._hand = rest
            self._carry()
            return False
        action, phase, ticks, target = self._arm
        above, grip = self._arm_goal()
        ticks += 1
        if phase == REACHING:                   # above the goal
            self._hand = self._hand + (above - self._hand) / max(1, REACH_TICKS - ticks + 1)
            if ticks >= REACH_TICKS:
                phase, ticks = GRASPING, 0
        elif phase == GRASPING:                 # down to grasp / to put down
            self._hand = above + (grip - above) * ticks / GRASP_TICKS
            if ticks >= GRASP_TICKS:
                if action == "pick":
                    self._held = target
                else:
                    self._put(self._held, grip[0], grip[1])
                    self._held = -1
                phase, ticks = LIFTING, 0
        elif phase == LIFTING:                  # lifting / releasing, back to rest
            self._hand = self._hand + (rest - self._hand) / max(1, REACH_TICKS - ticks + 1)
            if ticks >= REACH_TICKS:
                phase = DONE
        self._arm_phase[action] = phase
        self._arm = None if phase == DONE else [action, phase, ticks, target]
        self._carry()
        return True

    def _carry(self):
        if self._held >= 0:
            self._objects[self._held, 2:5] = self._hand - [0.0, 0.0, self.block_size]

    def _arm_joints(self):
        """Shoulder, elbow and hand positions (mm) of the two-link arm reaching the hand."""
        shoulder, hand = self._shoulder(), self._hand
        link = self.arm_length / 2
        offset = hand - shoulder
        distance = min(float(np.linalg.norm(offset)), 2 * link - 1e-6)
        if distance < 1e-9:
            return shoulder, shoulder + [0, 0, link], hand
        direction = offset / np.linalg.norm(offset)
        side = np.cross(direction, [0.0, 0.0, 1.0])
        up = np.cross(side, direction) if np.linalg.norm(side) > 1e-9 else np.array([1.0, 0, 0])
        up /= np.linalg.norm(up)
        rise = math.sqrt(max(link * link - (distance / 2) ** 2, 0.0))
        elbow = shoulder + direction * distance / 2 + up * rise
        return shoulder, elbow, shoulder + direction * distance

    # --- charging ------------------------------------------------------------------------------

    def _charge(self):
        self._charging = False
        if self.CHARGE_BATTERIES is None or _first(self.CHARGE_BATTERIES) <= 0.5:
            self._errors["CHARGE_ERROR"] = 0.0
            return
        station = np.asarray(self.charging_station, float)
        if math.hypot(*(self._pose[:2] - station)) <= CHARGE_DISTANCE:
            self._errors["CHARGE_ERROR"] = 0.0
            self._charging = True
            self._battery = min(1.0, self._battery + CHARGE_RATE)
        else:
            self._errors["CHARGE_ERROR"] = 1.0

    # --- outputs -------------------------------------------------------------------------------

    def _rows(self, kind, mask=None):
        chosen = np.flatnonzero(self._objects[:, 0] == kind)
        if mask is not None:
            chosen = chosen[mask[chosen]]
        table = np.zeros((MAX_ROWS, 6)) if mask is not None else \
            _empty_table(self.empty_rows == "whole")
        for k, i in enumerate(chosen):
            table[k, :5] = self._objects[i, 1:6]
            table[k, 5] = 1.0 if i == self._held else 0.0
        return table

    @staticmethod
    def _one_hot(out, index):
        out.fill(0.0)
        if index is not None:
            out[index] = 1.0

    def _write(self):
        x, y, heading = self._pose
        self.OBJECTS_OUT.reshape(-1)[:self._objects.size] = self._objects.reshape(-1)
        self.BLOCKS[...] = self._rows(BLOCK)
        self.LANDMARKS[...] = self._rows(LANDMARK)
        self.CHARGING_STATION[...] = self.charging_station
        centre = np.array([x + self.view_distance * math.cos(heading),
                           y + self.view_distance * math.sin(heading)])
        self.VIEW_FIELD[...] = centre
        seen = np.hypot(self._objects[:, 2] - centre[0], self._objects[:, 3] - centre[1]) <= \
            self.view_radius
        self.BLOCKS_IN_VIEW[...] = self._rows(BLOCK, seen)
        self.ROBOT_LOCATION[...] = (x, y, self._objects[self._held, 1] if self._held >= 0
                                    else 0.0, heading)
        self.SPEED_OUT[0] = _first(self.SPEED, 1.0)
        self.BATTERY_LEVEL[0] = self._battery
        self._write_target()
        self._one_hot(self.LOCOMOTION_PHASE, self._locomotion)
        for action in ("pick", "place"):
            phase = self._arm_phase[action]
            self._one_hot(getattr(self, f"{action.upper()}_PHASE"),
                          None if phase == IDLE else phase)
        self._one_hot(self.CHARGE_PHASE, 1 if self._charging else None)
        for name, value in self._errors.items():
            getattr(self, name)[0] = value
        self._write_ranges()
        self._write_transforms()

    def _write_target(self):
        if self._arm is not None:
            _, grip = self._arm_goal()
            self.TARGET[...] = (*grip, 2 if self._arm[0] == "pick" else 3)
        elif self._locomotion in (TURNING, DRIVING) and self._goal is not None:
            self.TARGET[...] = (*self._goal, 0.0, 1.0)
        else:
            self.TARGET.fill(EMPTY)

    def _write_ranges(self):
        x, y, heading = self._pose
        objects = [(ox, oy, self.block_size / 2, colour)
                   for i, (kind, _, ox, oy, _, colour) in enumerate(self._objects)
                   if kind in (BLOCK, LANDMARK) and i != self._held]
        self.RANGE_MAP[...], self.RANGE_COLOR[...] = range_map(
            self._walls, x, y, heading, self.range_limit, objects,
            even=self.range_sectors == "even")

    def _write_transforms(self):
        x, y, heading = self._pose
        mm = 0.001
        rows = [_placed_transform((x * mm, y * mm, ROBOT_HEIGHT / 2 * mm), heading,
                                  np.array([2 * self.robot_radius, 2 * self.robot_radius,
                                            ROBOT_HEIGHT]) * mm)]
        shoulder, elbow, hand = (p * mm for p in self._arm_joints())
        thick = 0.02
        rows.append(_segment_transform(shoulder, elbow, thick))
        rows.append(_segment_transform(elbow, hand, thick))
        rows.append(_placed_transform(hand, heading, (0.04, 0.06, 0.02)))
        sx, sy = self.charging_station
        rows.append(_placed_transform((sx * mm, sy * mm, 0.05), 0.0, (0.1, 0.1, 0.1)))
        size = self.block_size * mm
        for kind, _, ox, oy, oz, _ in self._objects:
            if kind == BLOCK:
                rows.append(_placed_transform((ox * mm, oy * mm, oz * mm + size / 2), 0.0,
                                              (size, size, size)))
            elif kind == LANDMARK:
                rows.append(_placed_transform((ox * mm, oy * mm, 2 * size), 0.0,
                                              (size, size, 4 * size)))
            else:
                rows.append(_placed_transform((0.0, 0.0, 0.0), 0.0, (0.0, 0.0, 0.0)))
        self.TRANSFORMS[...] = np.array([r.reshape(-1) for r in rows])
