"""GLRobotSimulator: a mobile builder robot with an arm that picks up and places blocks."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter

MAX_ROWS = 50
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
    return value is not None and value.reshape(-1)[0] > 0.5 and previous <= 0.5


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
    """A simulated builder robot (after the Goal-Leaders robot of Ikaros 2) in a square arena
    seen from above, in millimetres: x, y on the floor, z up, headings in radians
    counter-clockwise from the x axis. OBJECTS_IN gives the objects on the first tick, one row
    each: kind (1 block, 2 landmark; 0 empty row), id, x, y, z, colour; OBJECTS_OUT is the same
    table as it is now. BLOCKS and LANDMARKS list them (id, x, y, z, colour, held), up to 50
    rows.

    Locomotion: a rising LOCOMOTION_TRIGGER starts a trip to GOAL_LOCATION (x, y): the robot
    turns at ``rotation_speed`` rad/tick, then drives at ``locomotion_speed`` mm/tick times
    SPEED (default 1). It stops with LOCOMOTION_ERROR when the goal is outside the arena, when
    it would run into a landmark, a block on the floor or a wall (its radius is
    ``robot_radius``) or when the battery is empty. DIRECT_CONTROL (forward mm/tick, rotation
    rad/tick) drives it directly while it is not zero.

    The arm (two links of ``arm_length``/2 from a shoulder 150 mm up, plus a gripper) reaches
    ``arm_length`` around the robot. A rising PICK_OBJECT_TRIGGER picks the block
    PICK_OBJECT_ID, or when that is 0 or unconnected the block nearest to
    PICK_OBJECT_SPATIAL_ATTENTION (x, y) within one block size; the block must be in reach, free
    (nothing on top) and the gripper empty. A rising PLACE_OBJECT_TRIGGER puts the held block at
    PLACE_OBJECT_LOCATION (x, y), in reach, on top of whatever is stacked there (``auto_stack``:
    a location within one block of a block snaps onto it). Each takes reaching (10 ticks),
    grasping or lowering (5), and lifting or releasing (10). MOVE_BLOCK (id, x, y) puts a block
    there at once (on top of a stack), for experiments.

    The battery (BATTERY_LEVEL, 0..1) loses ``battery_decay`` per tick, twice that while the
    robot or its arm moves; CHARGE_BATTERIES above 0.5 charges it by 0.01 per tick when the
    robot is within 100 mm of ``charging_station`` (otherwise CHARGE_ERROR).

    Phases are one-hot: LOCOMOTION_PHASE (idle, turning, driving, arrived, failed), PICK_PHASE
    and PLACE_PHASE (idle, reaching, grasping / lowering, lifting / releasing, done),
    CHARGE_PHASE (not charging, charging); an error output is 1 from a failure until the next
    trigger of the same action. ROBOT_LOCATION is (x, y, heading, id of the held block or 0);
    TARGET the goal of the running action (x, y, z, 1 locomotion / 2 pick / 3 place; 0 idle);
    VIEW_FIELD the centre of the disc of radius ``view_radius`` in front of the robot that it
    sees, and BLOCKS_IN_VIEW the blocks in it. RANGE_MAP is the distance (mm, at most
    ``view_radius``) to the nearest object or wall along 32 directions around the robot,
    starting at its heading and going counter-clockwise, and RANGE_COLOR the colour of what each
    ray hits (0: a wall or nothing). TRANSFORMS draws the scene in the web UI's 3-D view
    (canvas3d, metres): rows of row-major 4x4 transforms of unit shapes: the body (cylinder),
    the upper arm, the forearm and the gripper (boxes), the charging station, and one row per
    OBJECTS_IN row (boxes for blocks, cylinders for landmarks; an empty row is scaled to
    nothing). Written from the Ikaros 2 class's interface; the row formats, phases and timings
    are this implementation's."""

    locomotion_speed = Parameter(10.0, "driving speed, mm per tick")
    rotation_speed = Parameter(0.1, "turning speed, radians per tick")
    arm_length = Parameter(300.0, "reach of the arm from the robot's centre, mm")
    charging_station = Parameter("1475 225", "position (x, y) of the charging station, mm",
                                 type="array")
    view_radius = Parameter(300.0, "radius of the disc the robot sees, mm")
    battery_decay = Parameter(0.0001, "battery used per tick (twice that while moving)")
    auto_stack = Parameter(False, "a block placed within one block size of another is "
                           "stacked on it")
    arena_size = Parameter("1500 1500", "width and depth of the arena, mm", type="array")
    start = Parameter("1300 225 3.1416", "the robot's start x, y (mm) and heading (rad)",
                      type="array")
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
    DIRECT_CONTROL = Input("forward speed (mm/tick) and rotation (rad/tick), used while not "
                           "zero", optional=True)

    OBJECTS_OUT = Output("the objects as they are now, rows as OBJECTS_IN",
                         shape="OBJECTS_IN.shape")
    BLOCKS = Output("the blocks: id, x, y, z, colour, held (1)", size_x="6", size_y="50")
    LANDMARKS = Output("the landmarks: id, x, y, z, colour, 0", size_x="6", size_y="50")
    CHARGING_STATION = Output("x, y of the charging station", size="2")
    VIEW_FIELD = Output("centre x, y of the disc the robot sees", size="2")
    TARGET = Output("x, y, z of the running action's goal, and the action (0 idle, 1 "
                    "locomotion, 2 pick, 3 place)", size="4")
    RANGE_MAP = Output("distance to the nearest object or wall in 32 directions, mm",
                       size="32")
    RANGE_COLOR = Output("colour of what each range ray hits (0: wall or nothing)", size="32")
    BLOCKS_IN_VIEW = Output("the blocks in the view field, rows as BLOCKS", size_x="6",
                            size_y="50")
    ROBOT_LOCATION = Output("x, y, heading of the robot and the id of the held block",
                            size="4")
    SPEED_OUT = Output("the robot's present speed, mm per tick", size="1")
    BATTERY_LEVEL = Output("the battery, 0..1", size="1")
    LOCOMOTION_PHASE = Output("one-hot: idle, turning, driving, arrived, failed", size="5")
    PICK_PHASE = Output("one-hot: idle, reaching, grasping, lifting, done", size="5")
    PLACE_PHASE = Output("one-hot: idle, reaching, lowering, releasing, done", size="5")
    CHARGE_PHASE = Output("one-hot: not charging, charging", size="2")
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
            raise ValueError(f"OBJECTS_IN has {self.OBJECTS_IN.size} values; it needs rows of "
                             "6 (kind, id, x, y, z, colour)")
        self._objects = np.zeros((self.OBJECTS_IN.size // 6, 6))
        self._loaded = False
        for name, count in (("arena_size", 2), ("start", 3), ("charging_station", 2)):
            if getattr(self, name).size != count:
                raise ValueError(f"{name} needs {count} values")
        x, y, heading = (float(v) for v in self.start)
        self._pose = np.array([x, y, heading])
        self._held = -1                                   # row index of the held block
        self._battery = 1.0
        self._speed = 0.0
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
        objects = np.asarray(self.OBJECTS_IN, np.float64).reshape(-1, 6).copy()
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
        if self._edge("LOCOMOTION_TRIGGER"):
            self._start_trip()
        if self._edge("PICK_OBJECT_TRIGGER"):
            self._start_pick()
        if self._edge("PLACE_OBJECT_TRIGGER"):
            self._start_place()
        direct = self.DIRECT_CONTROL
        if direct is not None and direct.size >= 2 and np.any(direct.reshape(-1)[:2] != 0):
            moving = self._drive(float(direct.flat[0]), float(direct.flat[1]))
        elif self._locomotion in (TURNING, DRIVING):
            moving = self._travel()
        else:
            self._speed = 0.0
        arm_moving = self._move_arm()
        self._charge()
        used = self.battery_decay * (2 if moving or arm_moving else 1)
        self._battery = max(0.0, self._battery - used)
        self._write()

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
        self._speed = 0.0

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
            self._pose[2] = heading + step
            if abs(turn) <= self.rotation_speed:
                self._locomotion = DRIVING
            return True
        speed = self.locomotion_speed * (_first(self.SPEED, 1.0) if self.SPEED is not None else 1.0)
        step = min(speed, distance)
        if not self._drive(step, 0.0):
            self._trip_failed()
            return False
        if step >= distance - 1e-9:
            self._pose[:2] = self._goal         # no rounding left over
            self._locomotion = ARRIVED
        return True

    def _drive(self, forward: float, rotation: float) -> bool:
        """Move forward (mm) after turning (rad); False (and no move) when blocked."""
        if self._battery <= 0:
            self._speed = 0.0
            return False
        x, y, heading = self._pose
        heading += rotation
        nx, ny = x + forward * math.cos(heading), y + forward * math.sin(heading)
        if forward and self._collides(nx, ny):
            self._pose[2] = heading
            self._speed = 0.0
            return False
        self._pose[:] = nx, ny, heading
        self._speed = abs(forward)
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
        table = np.zeros((MAX_ROWS, 6))
        for k, i in enumerate(chosen):
            table[k, :5] = self._objects[i, 1:6]
            table[k, 5] = 1.0 if i == self._held else 0.0
        return table

    def _one_hot(self, out, index):
        out.fill(0.0)
        out[index] = 1.0

    def _write(self):
        x, y, heading = self._pose
        self.OBJECTS_OUT.reshape(-1)[...] = self._objects.reshape(-1)
        self.BLOCKS[...] = self._rows(BLOCK)
        self.LANDMARKS[...] = self._rows(LANDMARK)
        self.CHARGING_STATION[...] = self.charging_station
        centre = np.array([x + self.view_radius * math.cos(heading),
                           y + self.view_radius * math.sin(heading)])
        self.VIEW_FIELD[...] = centre
        seen = np.hypot(self._objects[:, 2] - centre[0], self._objects[:, 3] - centre[1]) <= \
            self.view_radius
        self.BLOCKS_IN_VIEW[...] = self._rows(BLOCK, seen)
        self.ROBOT_LOCATION[...] = (x, y, heading,
                                    self._objects[self._held, 1] if self._held >= 0 else 0.0)
        self.SPEED_OUT[0] = self._speed
        self.BATTERY_LEVEL[0] = self._battery
        self._write_target()
        self._one_hot(self.LOCOMOTION_PHASE, self._locomotion)
        self._one_hot(self.PICK_PHASE, self._arm_phase["pick"])
        self._one_hot(self.PLACE_PHASE, self._arm_phase["place"])
        self._one_hot(self.CHARGE_PHASE, 1 if self._charging else 0)
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
            self.TARGET.fill(0.0)

    def _write_ranges(self):
        x, y, heading = self._pose
        width, depth = (float(v) for v in self.arena_size)
        radius = self.block_size / 2
        for k in range(32):
            angle = heading + 2 * math.pi * k / 32
            c, s = math.cos(angle), math.sin(angle)
            best, colour = float(self.view_radius), 0.0
            for wall in ((-x / c if c < 0 else (width - x) / c) if c else math.inf,
                         (-y / s if s < 0 else (depth - y) / s) if s else math.inf):
                best = min(best, wall)
            for i, (kind, _, ox, oy, _, col) in enumerate(self._objects):
                if kind not in (BLOCK, LANDMARK) or i == self._held:
                    continue
                along = (ox - x) * c + (oy - y) * s
                across2 = (ox - x) ** 2 + (oy - y) ** 2 - along * along
                if along > 0 and across2 <= radius * radius:
                    hit = along - math.sqrt(radius * radius - across2)
                    if hit < best:
                        best, colour = hit, col
            self.RANGE_MAP[k] = max(best, 0.0)
            self.RANGE_COLOR[k] = colour

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
