"""EpiHeadPose: the pose of the Epi head from its joint angles, for the 3-D view (used by epi.ikg)."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter
from ikaros.modules.robot.GazeController import head_frame


class EpiHeadPose(Module):
    """Forward kinematics of the 4-DOF stereo head that GazeController aims (same geometry
    parameters A, B, C, D and origin). ANGLES is (neck pan, neck tilt, left eye pan, right eye
    pan) in degrees plus ``offset`` (180: the servo angles of a Dynamixel). TRANSFORMS has one
    row-major 4×4 transform a row, for the canvas3d widget: the neck joint, the head (at the
    tilt axis), the point between the eyes, the left eye, the right eye and TARGET."""

    A = Parameter(0.077, "height of the tilt axis above the neck pan joint, metres")
    B = Parameter(0.120, "height of the eyes above the tilt axis, metres")
    C = Parameter(0.060, "distance of the eyes in front of the tilt axis, metres")
    D = Parameter(0.060, "distance between the eyes, metres")
    origin = Parameter("0 0 0.693", "position of the neck pan joint, metres", type="array")
    offset = Parameter(180.0, "subtracted from every angle (degrees)")

    ANGLES = Input("neck pan, neck tilt, left eye pan, right eye pan (degrees + offset)")
    TARGET = Input("the point looked at (x, y, z), metres", optional=True)
    TRANSFORMS = Output("neck, head, eyes centre, left eye, right eye, target: 4x4 transforms, one a row",
                        size="6, 16")

    def tick(self):
        pan, tilt, left_eye, right_eye = (math.radians(a - self.offset) for a in self.ANGLES.reshape(-1)[:4])
        origin = np.asarray(self.origin, np.float64)
        forward, left, up = head_frame(pan, tilt)
        neck_forward, neck_left, _ = head_frame(pan, 0.0)
        axis = origin + [0.0, 0.0, self.A]
        centre = axis + self.B * up + self.C * forward
        rows = [(np.column_stack([neck_forward, neck_left, [0, 0, 1]]), origin),
                (np.column_stack([forward, left, up]), axis),
                (np.column_stack([forward, left, up]), centre)]
        for eye, side in ((left_eye, 0.5), (right_eye, -0.5)):
            c, s = math.cos(eye), math.sin(eye)
            rows.append((np.column_stack([c * forward + s * left, -s * forward + c * left, up]),
                         centre + side * self.D * left))
        target = self.TARGET.reshape(-1)[:3] if self.TARGET is not None else centre
        rows.append((np.eye(3), target))
        for k, (rotation, position) in enumerate(rows):
            transform = np.eye(4)
            transform[:3, :3] = rotation
            transform[:3, 3] = position
            self.TRANSFORMS[k] = transform.reshape(-1)
