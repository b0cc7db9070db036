"""GazeController: inverse kinematics of a 4-DOF stereo head (neck pan and tilt, two eye pans)."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter

UNIT_PER_RADIAN = {"degrees": 180.0 / math.pi, "radians": 1.0, "tau": 1.0 / (2.0 * math.pi)}


def head_frame(pan: float, tilt: float):
    """Unit vectors (forward, left, up) of the head after neck ``pan`` and ``tilt`` (radians)."""
    cp, sp, ct, st = math.cos(pan), math.sin(pan), math.cos(tilt), math.sin(tilt)
    forward = np.array([ct * cp, ct * sp, st])
    left = np.array([-sp, cp, 0.0])
    up = np.array([-st * cp, -st * sp, ct])
    return forward, left, up


def gaze_angles(target, origin, A, B, C, D):
    """The joint angles (pan, tilt, left eye, right eye) in radians that aim both eyes at
    ``target``, or None when the target is closer to the tilt axis than the eye height B.

    The head is panned so that its midplane holds the target, and tilted so that the line
    through the eyes' pan axes (height B above the tilt axis, C in front of it) is level with
    the target in the head frame; each eye then pans in that plane to look at the target."""
    t = np.asarray(target, np.float64) - np.asarray(origin, np.float64)
    pan = math.atan2(t[1], t[0])
    reach = math.hypot(t[0], t[1])
    height = t[2] - A
    distance = math.hypot(reach, height)
    if distance <= B:
        return None
    tilt = math.atan2(height, reach) - math.asin(B / distance)
    forward = reach * math.cos(tilt) + height * math.sin(tilt) - C   # target ahead of the eyes
    left_eye = math.atan2(-D / 2.0, forward)
    right_eye = math.atan2(D / 2.0, forward)
    return pan, tilt, left_eye, right_eye


class GazeController(Module):
    """Inverse kinematics for a stereo head with four joints (the Epi head): neck pan, neck
    tilt, and the pan of each eye. INPUT is the target (x, y, z) in metres in the robot's
    frame: x forward, y to the left, z up; ``target`` is used instead when
    ``target_override`` is on. The neck pan joint stands at ``origin``; the tilt axis is
    ``A`` above it; the eyes' pan axes are ``B`` above and ``C`` in front of the tilt axis,
    ``D`` apart. OUTPUT is (neck pan, neck tilt, left eye pan, right eye pan): pan and eye
    angles are positive to the left, tilt is positive upwards, 0 looks straight ahead, in
    ``angle_unit`` plus ``offset`` (an offset of 180 degrees gives the servo angles of Ikaros 2
    Dynamixel models, where 180 is a servo's centre). The neck pans the head's midplane onto
    the target and tilts it until the eyes are level with the target; the eyes then converge
    on it. With the defaults the target 0.5 0 0.89 is straight ahead at eye height. A target
    within B of the tilt axis cannot be looked at: the angles hold and a warning is given.
    VIEW_SIDE (9 line segments x0 y0 x1 y1, metres; horizontal: distance from the pan axis
    along the gaze, vertical: height) and VIEW_TOP (14 segments, x and y from above) draw
    the head for the `path` widget. Side view rows: line of sight, neck, head riser, head
    forward to the eyes, four edges of the head, eye. Top view rows: four edges of the
    head, the eye baseline, left eye, right eye, left and right lines of sight, neck to the
    eyes, the target cross (two), and the left and right lenses. Written from the Ikaros 2
    class's interface; its drawing coordinates are not known and may differ."""

    A = Parameter(0.077, "height of the neck tilt axis above the neck pan joint, metres")
    B = Parameter(0.120, "height of the eyes' pan axes above the tilt axis, metres")
    C = Parameter(0.060, "distance of the eyes' pan axes in front of the tilt axis, metres")
    D = Parameter(0.060, "distance between the two eyes, metres")
    E = Parameter(0.040, "length of an eye in the drawings, metres")
    target = Parameter("0.5 0 0.89", "the target (x, y, z) used when target_override is on",
                       type="array")
    target_override = Parameter(False, "use the target parameter instead of INPUT")
    origin = Parameter("0 0 0.693", "position (x, y, z) of the neck pan joint, metres",
                       type="array")
    angle_unit = Parameter("degrees", "unit of the output angles",
                           options="degrees/radians/tau")
    offset = Parameter(0.0, "added to every output angle, in angle_unit (180 for Dynamixel "
                       "servos in degrees)")

    INPUT = Input("the target (x, y, z) to look at, metres")

    OUTPUT = Output("neck pan, neck tilt, left eye pan, right eye pan", size="4")
    VIEW_SIDE = Output("side view of the head: 9 line segments (x0, y0, x1, y1)",
                       size_x="4", size_y="9")
    VIEW_TOP = Output("top view of the head: 14 line segments (x0, y0, x1, y1)",
                      size_x="4", size_y="14")

    def init(self):
        if self.INPUT.size < 3 and not self.target_override:
            raise ValueError(f"INPUT has {self.INPUT.size} elements; it needs 3 (x, y, z)")
        for name in ("target", "origin"):
            if getattr(self, name).size != 3:
                raise ValueError(f"{name} needs three values (x, y, z)")
        self._angles = (0.0, 0.0, 0.0, 0.0)
        self._warned = False
        self._write(self._current_target())

    def _current_target(self):
        source = self.target if self.target_override else self.INPUT.reshape(-1)[:3]
        return np.asarray(source, np.float64)

    def tick(self):
        target = self._current_target()
        angles = gaze_angles(target, self.origin, self.A, self.B, self.C, self.D)
        if angles is None:
            if not self._warned:
                self.warning(f"cannot look at {target.tolist()}: closer than B = {self.B} "
                             "to the tilt axis; holding the angles")
                self._warned = True
        else:
            self._angles = angles
            self._warned = False
        self._write(target)

    def _write(self, target):
        scale = UNIT_PER_RADIAN[self.angle_unit]
        self.OUTPUT[...] = np.asarray(self._angles) * scale + self.offset
        self.VIEW_SIDE[...] = self._side_view(target)
        self.VIEW_TOP[...] = self._top_view(target)

    def _side_view(self, target):
        pan, tilt = self._angles[0], self._angles[1]
        origin = np.asarray(self.origin, np.float64)
        t = target - origin
        f = np.array([math.cos(tilt), math.sin(tilt)])
        u = np.array([-math.sin(tilt), math.cos(tilt)])
        base = np.array([0.0, origin[2]])
        axis = base + [0.0, self.A]
        riser = axis + self.B * u
        eyes = riser + self.C * f
        aim = np.array([t[0] * math.cos(pan) + t[1] * math.sin(pan), target[2]])
        corners = [axis + a * f + b * u for a, b in
                   ((-self.C / 2, 0), (self.C, 0), (self.C, self.B + self.E / 2),
                    (-self.C / 2, self.B + self.E / 2))]
        segments = [(eyes, aim), (base, axis), (axis, riser), (riser, eyes)]
        segments += [(corners[i], corners[(i + 1) % 4]) for i in range(4)]
        segments.append((eyes, eyes + self.E * f))
        return [np.concatenate(s) for s in segments]

    def _top_view(self, target):
        pan, tilt, left_eye, right_eye = self._angles
        forward, left, up = head_frame(pan, tilt)
        origin = np.asarray(self.origin, np.float64)
        axis = origin + [0.0, 0.0, self.A]
        middle = axis + self.B * up + self.C * forward
        eye_l = middle + self.D / 2 * left
        eye_r = middle - self.D / 2 * left
        gaze_l = math.cos(left_eye) * forward + math.sin(left_eye) * left
        gaze_r = math.cos(right_eye) * forward + math.sin(right_eye) * left
        tip_l, tip_r = eye_l + self.E * gaze_l, eye_r + self.E * gaze_r
        lens_l = np.cross(up, gaze_l) * self.E / 4
        lens_r = np.cross(up, gaze_r) * self.E / 4
        corners = [axis + a * forward + b * left for a, b in
                   ((-self.C / 2, -self.D), (self.C, -self.D), (self.C, self.D),
                    (-self.C / 2, self.D))]
        cross = self.E / 2
        segments = [(corners[i], corners[(i + 1) % 4]) for i in range(4)]
        segments += [(eye_l, eye_r), (eye_l, tip_l), (eye_r, tip_r), (eye_l, target),
                     (eye_r, target), (origin, middle),
                     (target - [cross, 0, 0], target + [cross, 0, 0]),
                     (target - [0, cross, 0], target + [0, cross, 0]),
                     (tip_l - lens_l, tip_l + lens_l), (tip_r - lens_r, tip_r + lens_r)]
        return [np.concatenate([a[:2], b[:2]]) for a, b in segments]
