"""PlanarArm: a three-joint arm in the unit square, and a target for it to reach."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._arm3 import Arm3, parameters as arm3_parameters

_LIMITS_LOW = np.array([-math.pi / 1.5, 0.0, 0.0])
_LIMITS_HIGH = np.array([math.pi / 1.5, math.pi, math.pi])
_RANDOM_INTERVAL = 100          # ticks between new random targets


def arm_joints(angles, segment_length, base=(0.5, 0.0)):
    """Forward kinematics: the (4, 2) joint positions of the arm for three joint angles.

    Angles are measured from the y axis (straight up), clockwise, each relative to the
    previous segment: joint k+1 = joint k + L_k (sin(a_0+...+a_k), cos(a_0+...+a_k))."""
    cumulative = np.cumsum(angles)
    steps = np.stack([np.sin(cumulative), np.cos(cumulative)], axis=1) * \
        np.asarray(segment_length, np.float64)[:, None]
    return np.vstack([base, np.asarray(base) + np.cumsum(steps, axis=0)])


def _outside(hand):
    """How far the hand is outside the frame 0.01..0.99 (0 inside)."""
    return float(np.sum(np.maximum(0.01 - hand, 0) + np.maximum(hand - 0.99, 0)))


class PlanarArm(Module):
    """A planar arm of three segments (lengths ``segment_length``, Ikaros 2: 0.35, 0.25,
    0.20) standing at (0.5, 0) in the unit square, and a target. Joint angles are measured
    clockwise from straight up, each relative to the previous segment, so joint k+1 =
    joint k + L_k·(sin(a_0+...+a_k), cos(a_0+...+a_k)). The angles start at 0.4 and move
    towards DESIRED_ANGLES (unconnected: the arm stays) at most ``speed`` radians per tick
    (all joints scaled together so the largest change is ``speed``), within the limits
    |a_0| <= 2π/3 and 0 <= a_1, a_2 <= π; a move that would take the hand outside
    0.01..0.99 in x or y is refused (unless it brings an outside hand closer to the frame:
    the start pose has the hand at x = 1.002, where Ikaros 2 could leave the arm stuck).
    The TARGET is redrawn uniformly in 0.1..0.9 at the start, every 100 ticks and whenever
    the hand comes within ``grasp_limit`` of it
    (``random``), or follows a path of radius ``target_range`` around (0.5, 0.5): ``linear``
    (x = 0.5 + range·sin(speed·t)), ``circular``, ``lisajous`` (y at 0.3 times the
    frequency) or ``square``; a grasp moves the time t of a path to a random point of its
    first 100 ticks. ``target_noise`` adds Gaussian noise to the TARGET output on every
    tick. DISTANCE is from the hand to the target of the same tick and CONTACT is 1 when it
    is below ``target_size``. (Ikaros 2 reported the distance to the previous tick's
    target, and with a random target let the noise accumulate as a random walk; here the
    noise does not accumulate.)

    Two interfaces: Ikaros 2 gives the angles on DESIRED_ANGLES, Ikaros 3 on JOINT_COMMAND
    (the same meaning; a model connects one of them). The Ikaros 3 GRIPPER input, when
    connected, decides grasps: the hand grasps the target on a tick when GRIPPER's first
    element is above 0 (closed) and the hand touches the target (CONTACT); ``grasp_limit``
    is then not used.

    In an Ikaros 3 file (dialect 3) the class is Ikaros 3's, a different simulation: a
    serial arm of ``link_lengths`` fixed at ``base_position`` in a world of world_width ×
    world_height units, its angles relative and counter-clockwise from +x, with a palm and
    two fingers (GRIPPER: 0 closed, 1 open) that push one movable circle
    (``movable_object``: x, y, radius) among fixed circles and lines. JOINT_COMMAND is
    reached in one tick unless a sub-step (at most ``max_joint_step``) hits the fixed world
    or leaves the object no place (``solver_iterations`` pushes), which stops the motion
    there and sets BLOCKED. RESET above 0.5 restarts from the initial pose. The outputs are
    Ikaros 3's (added in dialect 3): JOINT_ANGLES, JOINT_POSITIONS, END_EFFECTOR (x, y, sum
    of the angles), MOVABLE_OBJECT (x, y, r, enclosed), LINK_CONTACTS, GRIPPER_CONTACTS
    (palm, left, right), OBJECT_CONTACTS (arm, circles, lines, world edge), BLOCKED,
    ENCLOSED (two or more gripper parts touch the object) and the World2D-style tables
    ARM_LINES, OBJECTS and WALLS; the Ikaros 2 outputs stay 0. Computed in float64 (Ikaros
    3 uses float32), so values may differ in the last digits; no run of the original was
    compared. Read this way, the reference's default scene puts the open right finger
    inside the lower fixed circle, so with every default the arm starts (and stays)
    BLOCKED; the reference does not settle whether the original does the same."""

    target_behavior = Parameter("random", "how the target moves",
                                options="random/linear/circular/lisajous/square")
    target_speed = Parameter(0.05, "angular speed of a moving target, radians per tick")
    target_size = Parameter(0.05, "CONTACT is 1 when the hand is closer than this")
    target_range = Parameter(0.3, "radius of the target's path around (0.5, 0.5)")
    target_noise = Parameter(0.0, "standard deviation of Gaussian noise added to TARGET")
    speed = Parameter(0.1, "largest change of a joint angle per tick, radians")
    grasp_limit = Parameter(0.0, "a hand closer than this to the target grasps it: a new "
                            "random target, or a jump along the path (0: never)")
    segment_length = Parameter("0.35 0.25 0.20", "lengths of the three segments",
                               type="array")
    seed = Parameter(None, "seed of the random generator; unset (or 0) gives a different "
                     "run every time", type="int")
    base_position = Parameter("60, 150", "Ikaros 3: where the arm is fixed", type="array")
    link_lengths = Parameter("65, 55, 45", "Ikaros 3: the length of each link", type="array")
    link_width = Parameter(6.0, "Ikaros 3: the width of the links")
    initial_joint_angles = Parameter("0, -0.5, 0.8", "Ikaros 3: the angles at the start and "
                                     "on RESET", type="array")
    joint_min = Parameter("-3.141593, -3.141593, -3.141593", "Ikaros 3: the lowest angles",
                          type="array")
    joint_max = Parameter("3.141593, 3.141593, 3.141593", "Ikaros 3: the highest angles",
                          type="array")
    max_joint_step = Parameter(0.01, "Ikaros 3: the largest change of a sub-step (radians)")
    initial_gripper = Parameter(1.0, "Ikaros 3: the gripper at the start (0 closed, 1 open)")
    palm_length = Parameter(34.0, "Ikaros 3: the length of the palm")
    finger_length = Parameter(32.0, "Ikaros 3: the length of the fingers")
    gripper_width = Parameter(5.0, "Ikaros 3: the width of the palm and fingers")
    finger_open_angle = Parameter(0.45, "Ikaros 3: the fingers' outward angle when open")
    finger_closed_angle = Parameter(0.65, "Ikaros 3: the fingers' inward angle when closed")
    movable_object = Parameter("205, 150, 12", "Ikaros 3: the movable circle: x, y, radius",
                               type="array")
    circle_obstacle_count = Parameter(2, "Ikaros 3: the number of fixed circles used",
                                      type="int", range=(0, None))
    circle_obstacles = Parameter("245, 105, 18; 245, 205, 18", "Ikaros 3: fixed circles, rows "
                                 "of x, y, radius", type="matrix")
    line_obstacle_count = Parameter(4, "Ikaros 3: the number of fixed lines used", type="int",
                                    range=(0, None))
    line_obstacles = Parameter("20, 20, 280, 20, 5; 280, 20, 280, 280, 5; 280, 280, 20, 280, "
                               "5; 20, 280, 20, 20, 5", "Ikaros 3: fixed lines, rows of x1, "
                               "y1, x2, y2, width", type="matrix")
    world_width = Parameter(300.0, "Ikaros 3: the width of the world")
    world_height = Parameter(300.0, "Ikaros 3: the height of the world")
    solver_iterations = Parameter(64, "Ikaros 3: the passes placing the movable object",
                                  type="int", range=(1, None))

    DESIRED_ANGLES = Input("Ikaros 2: the three joint angles the arm moves towards",
                           optional=True)
    JOINT_COMMAND = Input("Ikaros 3: the three joint angles the arm moves towards",
                          optional=True)
    GRIPPER = Input("Ikaros 3: above 0 closes the gripper, which grasps a touched target",
                    optional=True)

    TARGET = Output("the target position (x, y)", size="2")
    JOINTS = Output("positions (x, y) of the base, the two inner joints and the hand, "
                    "one row each", size_x="2", size_y="4")
    ANGLES = Output("the three joint angles", size="3")
    HAND_POSITION = Output("the hand position (x, y)", size="2")
    DISTANCE = Output("distance from the hand to the target", size="1")
    CONTACT = Output("1 when the hand touches the target (DISTANCE < target_size)",
                     size="1")

    def configure(self):
        if self.dialect != "3":
            return
        self.add_input("RESET", optional=True, description="above 0.5 restarts the arm")
        p = arm3_parameters(self)
        L, circles, lines = len(p.link_lengths), len(p.circles), len(p.lines)
        for name, shape in (("JOINT_ANGLES", (L,)), ("JOINT_POSITIONS", (L + 1, 2)),
                            ("END_EFFECTOR", (3,)), ("MOVABLE_OBJECT", (4,)),
                            ("LINK_CONTACTS", (L,)), ("GRIPPER_CONTACTS", (3,)),
                            ("OBJECT_CONTACTS", (4,)), ("BLOCKED", (1,)), ("ENCLOSED", (1,)),
                            ("ARM_LINES", (L + 3, 11)), ("OBJECTS", (circles + 1, 18)),
                            ("WALLS", (L + 3 + lines, 11))):
            self.add_output(name, shape, "Ikaros 3 (see the description)")

    def init(self):
        self._arm3 = None
        if self.dialect == "3":
            self._arm3 = Arm3(arm3_parameters(self))
            self._arm3.sense()
            self._arm3.write(self)
            return
        if self.segment_length.size != 3:
            raise ValueError("segment_length needs three values")
        if self.DESIRED_ANGLES is not None and self.JOINT_COMMAND is not None:
            raise ValueError("connect DESIRED_ANGLES (Ikaros 2) or JOINT_COMMAND (Ikaros 3), "
                             "not both")
        self._command, name = (self.JOINT_COMMAND, "JOINT_COMMAND") \
            if self.JOINT_COMMAND is not None else (self.DESIRED_ANGLES, "DESIRED_ANGLES")
        if self._command is not None and self._command.size < 3:
            raise ValueError(f"{name} has {self._command.size} elements; it needs 3")
        self._rng = np.random.default_rng(self.seed or None)
        self._angles = np.full(3, 0.4)
        self._t = 0
        self._target = np.array([0.5, 0.5])
        self._new_random_target()
        self._update_arm()
        self._write_target()

    def _joints(self, angles):
        return arm_joints(angles, self.segment_length.astype(np.float64))

    def _update_arm(self):
        np.clip(self._angles, _LIMITS_LOW, _LIMITS_HIGH, out=self._angles)
        joints = self._joints(self._angles)
        self.JOINTS[...] = joints
        self.HAND_POSITION[...] = joints[3]
        self.ANGLES[...] = self._angles

    def _new_random_target(self):
        if self.target_behavior == "random":
            self._target = self._rng.uniform(0.1, 0.9, 2)
        self._since_new = 0

    def _tick3(self):
        arm = self._arm3
        if self.RESET is not None and self.RESET.size and self.RESET.flat[0] > 0.5:
            for flags in arm.flags:
                flags[...] = 0
            arm.reset()
        else:
            command = None if self.JOINT_COMMAND is None else \
                self.JOINT_COMMAND.reshape(-1).astype(float)
            grip = None if self.GRIPPER is None or not self.GRIPPER.size else \
                float(self.GRIPPER.flat[0])
            arm.move(command, grip)
        arm.sense()
        arm.write(self)

    def tick(self):
        if self._arm3 is not None:
            self._tick3()
            return
        if self._command is not None:
            self._move_arm()
        distance = float(np.hypot(*(self.HAND_POSITION - self.TARGET)))
        if self.GRIPPER is not None:
            grasped = bool(self.GRIPPER.size and self.GRIPPER.flat[0] > 0) and \
                distance < self.target_size
        else:
            grasped = distance < self.grasp_limit
        self._since_new += 1
        if self.target_behavior == "random":
            if grasped or self._since_new >= _RANDOM_INTERVAL:
                self._new_random_target()
        else:
            if grasped:
                self._t = int(self._rng.integers(0, 100))
            self._t += 1
        self._write_target()

    def _move_arm(self):
        desired = np.asarray(self._command, np.float64).reshape(-1)[:3]
        movement = desired - self._angles
        largest = np.max(np.abs(movement))
        if largest > self.speed:
            movement *= self.speed / largest
        new = np.clip(self._angles + movement, _LIMITS_LOW, _LIMITS_HIGH)
        outside = _outside(self._joints(new)[3])
        if outside == 0 or outside < _outside(self._joints(self._angles)[3]):
            self._angles = new
        self._update_arm()

    def _path_target(self):
        phase = self.target_speed * self._t
        r = self.target_range
        s, c = math.sin(phase), math.cos(phase)
        kind = self.target_behavior
        if kind == "linear":
            return np.array([0.5 + r * s, 0.5])
        if kind == "circular":
            return np.array([0.5 + r * s, 0.5 + r * c])
        if kind == "lisajous":
            return np.array([0.5 + r * s, 0.5 + r * math.cos(0.3 * phase)])
        norm = abs(s) + abs(c)                              # square
        return np.array([0.5 + r * s / norm, 0.5 + r * c / norm])

    def _write_target(self):
        target = self._target if self.target_behavior == "random" else self._path_target()
        if self.target_noise > 0:
            target = target + self._rng.normal(0, self.target_noise, 2)
        self.TARGET[...] = target
        d = float(np.hypot(*(self.HAND_POSITION - self.TARGET)))
        self.DISTANCE[0] = d
        self.CONTACT[0] = 1.0 if d < self.target_size else 0.0
