"""PlanarArm: a three-joint arm in the unit square and a target for it to reach (Ikaros 2),
or Ikaros 3's arm with a gripper that pushes an object among obstacles."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from .._crand import module_rand
from ._arm2 import (RANDOM_INTERVAL, START_ANGLES, arm_joints, inside_frame, next_angles,
                    path_target)
from ._arm3 import Arm3, parameters as arm3_parameters


class PlanarArm(Module):
    """A planar arm and something to reach; an Ikaros 2 file gets Ikaros 2's simulation, an
    Ikaros 3 file Ikaros 3's, a different one.

    **Ikaros 2.** Three segments (lengths ``segment_length``: 0.35, 0.25, 0.20) standing at
    (0.5, 0) in the unit square. Joint angles are measured clockwise from straight up, each
    relative to the previous segment: joint k+1 = joint k + L_k·(sin(a_0+…+a_k),
    cos(a_0+…+a_k)). The angles start at 0.4. Each tick, with DESIRED_ANGLES d (the first
    three elements; unconnected, the arm stays): when the largest |d − a| is 1 radian or
    more the angles move ``speed`` × (d − a), otherwise they take d at once; then they are
    limited to |a_0| ≤ 2π/3 and 0 ≤ a_1, a_2 ≤ π, and the move is refused (the arm stays)
    if it would put the hand outside 0.01 … 0.99 in x or y. (The start pose has the hand at
    x = 1.002, outside: the arm leaves it only by a move that ends inside.) DISTANCE is
    from the hand to the TARGET of the previous tick (0, 0 before the first), CONTACT is 1
    when it is below ``target_size``; then the target moves. With ``random`` a new target,
    uniform in 0.1 … 0.9 (x drawn first), is drawn on tick 0, every 100 ticks and whenever
    the hand is within ``grasp_limit`` of it; the draws are the C library's ``rand()`` of
    the network (``rand()/RAND_MAX``), unseeded as in Ikaros 2, so a model gives the
    original's targets, or a stream of its own seeded with ``seed``. The golden files of
    Ikaros 2 show the motion rule, the start, the limits a_1 ≥ 0, the refused moves and the
    random targets at the default ``speed``; the other limits, the paths and the noise
    follow this project's reading of the class description: ``linear``,
    ``circular``, ``lisajous`` and ``square`` follow a path of radius ``target_range``
    around (0.5, 0.5) at phase ``target_speed`` × t (t = 1 on tick 0; x = 0.5 + range·sin,
    circular y = 0.5 + range·cos, lisajous y at 0.3 times the frequency), a grasp moving t
    to a random point of the first 100 ticks; ``target_noise`` adds Gaussian noise to the
    TARGET output on every tick (it does not accumulate). The Ikaros 3 inputs work here
    too: JOINT_COMMAND as DESIRED_ANGLES, and GRIPPER (when connected) decides grasps:
    the hand grasps the target on a tick when GRIPPER's first element is above 0 and
    CONTACT is 1. The Ikaros 3 outputs stay 0.

    **Ikaros 3** (an Ikaros 3 file): a serial arm of ``link_lengths`` fixed at
    ``base_position`` in a world of world_width × world_height units, its angles relative
    and counter-clockwise from +x, with a palm and two fingers (GRIPPER: 0 closed, 1 open)
    that push one movable circle (``movable_object``: x, y, radius) among fixed circles and
    lines. JOINT_COMMAND is reached in one tick unless a sub-step (at most
    ``max_joint_step``) hits the fixed world or leaves the object no place
    (``solver_iterations`` pushes), which stops the motion there and sets BLOCKED. RESET
    above 0.5 restarts from the initial pose. The outputs: JOINT_ANGLES, JOINT_POSITIONS,
    END_EFFECTOR (x, y, sum of the angles), MOVABLE_OBJECT (x, y, r, enclosed),
    LINK_CONTACTS, GRIPPER_CONTACTS (palm, left, right), OBJECT_CONTACTS (arm, circles,
    lines, world edge), BLOCKED, ENCLOSED (two or more gripper parts touch the object) and
    the World2D-style tables ARM_LINES, OBJECTS and WALLS; the Ikaros 2 outputs stay 0.
    Computed in float64 (Ikaros 3 uses float32), so values may differ in the last digits;
    no run of the original was compared. Read this way, the reference's default scene puts
    the open right finger inside the lower fixed circle, so with every default the arm
    starts (and stays) BLOCKED; the reference does not settle whether the original does
    the same."""

    target_behavior = Parameter("random", "how the target moves",
                                options="random/linear/circular/lisajous/square")
    target_speed = Parameter(0.05, "angular speed of a moving target, radians per tick")
    target_size = Parameter(0.05, "CONTACT is 1 when the hand is closer than this")
    target_range = Parameter(0.3, "radius of the target's path around (0.5, 0.5)")
    target_noise = Parameter(0.0, "standard deviation of Gaussian noise added to TARGET")
    speed = Parameter(0.1, "the fraction of the change to DESIRED_ANGLES moved per tick "
                      "when the largest change is 1 radian or more")
    grasp_limit = Parameter(0.0, "a hand closer than this to the target grasps it: a new "
                            "random target, or a jump along the path (0: never)")
    segment_length = Parameter("0.35 0.25 0.20", "lengths of the three segments",
                               type="array")
    seed = Parameter(None, "a random stream of the module's own, srand(seed); unset (or "
                     "0): the network's C rand(), as Ikaros 2 (the same targets every run)",
                     type="int")
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
    JOINT_COMMAND = Input("Ikaros 3: the joint angles the arm moves to (in an Ikaros 2 "
                          "file: as DESIRED_ANGLES)", optional=True)
    GRIPPER = Input("Ikaros 3: 0 closed … 1 open (in an Ikaros 2 file: above 0 grasps a "
                    "touched target)", optional=True)
    RESET = Input("Ikaros 3: above 0.5 restarts the arm from its initial pose",
                  optional=True)

    TARGET = Output("Ikaros 2: the target position (x, y)", size="2")
    JOINTS = Output("Ikaros 2: positions (x, y) of the base, the two inner joints and the "
                    "hand, one row each", size_x="2", size_y="4")
    ANGLES = Output("Ikaros 2: the three joint angles", size="3")
    HAND_POSITION = Output("Ikaros 2: the hand position (x, y)", size="2")
    DISTANCE = Output("Ikaros 2: distance from the hand to the previous tick's target",
                      size="1")
    CONTACT = Output("Ikaros 2: 1 when DISTANCE < target_size", size="1")
    JOINT_ANGLES = Output("Ikaros 3: the joint angles (one per link)")
    JOINT_POSITIONS = Output("Ikaros 3: the base and the end of each link (x, y), one row "
                             "each")
    END_EFFECTOR = Output("Ikaros 3: the hand: x, y and the sum of the angles", size="3")
    MOVABLE_OBJECT = Output("Ikaros 3: the movable circle: x, y, radius, enclosed",
                            size="4")
    LINK_CONTACTS = Output("Ikaros 3: 1 for each link that touches the movable object")
    GRIPPER_CONTACTS = Output("Ikaros 3: palm, left and right finger touch the object",
                              size="3")
    OBJECT_CONTACTS = Output("Ikaros 3: the object touches the arm, a fixed circle, a fixed "
                             "line, the world's edge", size="4")
    BLOCKED = Output("Ikaros 3: 1 when this tick's motion was stopped", size="1")
    ENCLOSED = Output("Ikaros 3: 1 when two or more gripper parts touch the object",
                      size="1")
    ARM_LINES = Output("Ikaros 3: the arm's segments as World2D wall rows (11 columns)")
    OBJECTS = Output("Ikaros 3: the movable object and the fixed circles as World2D object "
                     "rows (18 columns)")
    WALLS = Output("Ikaros 3: the arm's segments and the fixed lines as World2D wall rows "
                   "(11 columns)")

    def set_sizes(self):
        p = arm3_parameters(self)
        links, circles, lines = len(p.link_lengths), len(p.circles), len(p.lines)
        for name, shape in (("JOINT_ANGLES", links), ("JOINT_POSITIONS", (links + 1, 2)),
                            ("LINK_CONTACTS", links), ("ARM_LINES", (links + 3, 11)),
                            ("OBJECTS", (circles + 1, 18)),
                            ("WALLS", (links + 3 + lines, 11))):
            self.set_output_shape(name, shape)

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
        self._random = module_rand(self)
        self._rng = np.random.default_rng(self.seed or None)
        self._angles = np.full(3, START_ANGLES)
        self._ticks = 0             # ticks run
        self._t = 0                 # time on a target path
        self._target = np.zeros(2)
        self._update_arm()

    def _joints(self, angles):
        return arm_joints(angles, self.segment_length.astype(np.float64))

    def _update_arm(self):
        joints = self._joints(self._angles)
        self.JOINTS[...] = joints
        self.HAND_POSITION[...] = joints[3]
        self.ANGLES[...] = self._angles

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
            desired = np.asarray(self._command, np.float64).reshape(-1)[:3]
            new = next_angles(self._angles, desired, self.speed)
            if inside_frame(self._joints(new)[3]):
                self._angles = new
            self._update_arm()
        distance = float(np.hypot(*(self.HAND_POSITION - self.TARGET)))
        self.DISTANCE[0] = distance
        self.CONTACT[0] = 1.0 if distance < self.target_size else 0.0
        if self.GRIPPER is not None:
            grasped = bool(self.GRIPPER.size and self.GRIPPER.flat[0] > 0) and \
                distance < self.target_size
        else:
            grasped = distance < self.grasp_limit
        if self.target_behavior == "random":
            if grasped or self._ticks % RANDOM_INTERVAL == 0:
                self._target = np.array([0.1 + 0.8 * self._random.uniform(),
                                         0.1 + 0.8 * self._random.uniform()])
            target = self._target
        else:
            if grasped:
                self._t = int(self._rng.integers(0, 100))
            self._t += 1
            target = path_target(self.target_behavior, self.target_speed * self._t,
                                 self.target_range)
        if self.target_noise > 0:
            target = target + self._rng.normal(0, self.target_noise, 2)
        self.TARGET[...] = target
        self._ticks += 1
