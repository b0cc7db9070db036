"""RotationConverter: converts 3-D poses between position, angle, matrix and quaternion
forms."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

_FORMATS = "xyz/xyzaxayaz/axayaz/matrix/quaternion"
_WIDTH = {"xyz": 3, "xyzaxayaz": 6, "axayaz": 3, "matrix": 16, "quaternion": 4}
_TO_RADIANS = {"degrees": np.pi / 180.0, "radians": 1.0, "tau": 2.0 * np.pi,
               "turns": 2.0 * np.pi}


def euler_to_matrices(ax, ay, az):
    """Rotation matrices R = Rz(az) @ Ry(ay) @ Rx(ax) for arrays of angles in radians:
    shape (n, 3, 3)."""
    cx, sx = np.cos(ax), np.sin(ax)
    cy, sy = np.cos(ay), np.sin(ay)
    cz, sz = np.cos(az), np.sin(az)
    r = np.empty(np.shape(ax) + (3, 3))
    r[..., 0, 0] = cz * cy
    r[..., 0, 1] = cz * sy * sx - sz * cx
    r[..., 0, 2] = cz * sy * cx + sz * sx
    r[..., 1, 0] = sz * cy
    r[..., 1, 1] = sz * sy * sx + cz * cx
    r[..., 1, 2] = sz * sy * cx - cz * sx
    r[..., 2, 0] = -sy
    r[..., 2, 1] = cy * sx
    r[..., 2, 2] = cy * cx
    return r


def matrices_to_euler(r):
    """The angles ax, ay, az (radians) with R = Rz(az) @ Ry(ay) @ Rx(ax); at gimbal lock
    (ay = +-90 degrees) ax is taken as 0."""
    cy = np.hypot(r[..., 2, 1], r[..., 2, 2])
    ay = np.arctan2(-r[..., 2, 0], cy)
    locked = cy < 1e-6
    ax = np.where(locked, 0.0, np.arctan2(r[..., 2, 1], r[..., 2, 2]))
    az = np.where(locked, np.arctan2(-r[..., 0, 1], r[..., 1, 1]),
                  np.arctan2(r[..., 1, 0], r[..., 0, 0]))
    return ax, ay, az


def quaternions_to_matrices(q):
    """Rotation matrices from quaternions (x, y, z, w), shape (n, 4) -> (n, 3, 3). The
    quaternions are normalised; a zero quaternion gives the identity."""
    q = np.asarray(q, dtype=np.float64)
    norm = np.linalg.norm(q, axis=-1, keepdims=True)
    zero = norm[..., 0] == 0
    q = np.where(norm > 0, q / np.where(norm > 0, norm, 1), [0.0, 0.0, 0.0, 1.0])
    x, y, z, w = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    r = np.empty(q.shape[:-1] + (3, 3))
    r[..., 0, 0] = 1 - 2 * (y * y + z * z)
    r[..., 0, 1] = 2 * (x * y - z * w)
    r[..., 0, 2] = 2 * (x * z + y * w)
    r[..., 1, 0] = 2 * (x * y + z * w)
    r[..., 1, 1] = 1 - 2 * (x * x + z * z)
    r[..., 1, 2] = 2 * (y * z - x * w)
    r[..., 2, 0] = 2 * (x * z - y * w)
    r[..., 2, 1] = 2 * (y * z + x * w)
    r[..., 2, 2] = 1 - 2 * (x * x + y * y)
    return r, zero


def matrices_to_quaternions(r):
    """Unit quaternions (x, y, z, w) with w >= 0 from rotation matrices (n, 3, 3), by the
    numerically stable choice among the four standard formulas."""
    m00, m11, m22 = r[..., 0, 0], r[..., 1, 1], r[..., 2, 2]
    trace = m00 + m11 + m22
    # Four times the square of each component; the largest gives the best-conditioned formula.
    cand = np.stack([1 + m00 - m11 - m22, 1 - m00 + m11 - m22, 1 - m00 - m11 + m22,
                     1 + trace], axis=-1)
    k = np.argmax(cand, axis=-1)
    s = np.sqrt(np.maximum(np.take_along_axis(cand, k[..., None], -1)[..., 0], 1e-300)) * 2
    d21, d02, d10 = r[..., 2, 1] - r[..., 1, 2], r[..., 0, 2] - r[..., 2, 0], \
        r[..., 1, 0] - r[..., 0, 1]
    s01, s02, s12 = r[..., 0, 1] + r[..., 1, 0], r[..., 0, 2] + r[..., 2, 0], \
        r[..., 1, 2] + r[..., 2, 1]
    q = np.empty(r.shape[:-2] + (4,))
    options = [np.stack([s / 4, s01 / s, s02 / s, d21 / s], -1),
               np.stack([s01 / s, s / 4, s12 / s, d02 / s], -1),
               np.stack([s02 / s, s12 / s, s / 4, d10 / s], -1),
               np.stack([d21 / s, d02 / s, d10 / s, s / 4], -1)]
    for i, option in enumerate(options):
        q[k == i] = option[k == i]
    q *= np.where(q[..., 3:4] < 0, -1.0, 1.0)
    return q / np.linalg.norm(q, axis=-1, keepdims=True)


class RotationConverter(Module):
    """Converts 3-D poses from one form to another. The forms are: ``xyz``, a position x, y,
    z; ``xyzaxayaz``, a position followed by Euler angles ax, ay, az; ``axayaz``, the angles
    alone; ``matrix``, a 4x4 homogeneous transform in row-major order (16 values: the
    rotation in the upper-left 3x3 block, the position in elements 3, 7 and 11); and
    ``quaternion``, a rotation as x, y, z, w (scalar last). The angles rotate about x, then
    y, then z (fixed axes), that is R = Rz(az) Ry(ay) Rx(ax), in ``angle_unit`` (degrees,
    radians, or tau, where 1 is a full turn). A 1-D input holds one pose and gives a 1-D
    output; a matrix input holds one pose per row and gives one output row per pose (a 4x4
    input in matrix form is one pose). Parts the output form has but the input lacks are
    neutral: no rotation, position 0. Ikaros 2 left quaternions unimplemented; here they
    work (``quaternions="computed"``). ``size_y`` x ``size_x`` (Ikaros 3's parameters,
    both 4 by default) is the block of the 4x4 transform that the matrix form holds: 3 x 4
    leaves out the last row, 3 x 3 is the rotation alone (this project's reading of the
    two parameters, which Ikaros 3 gives as the output's size; no reference gives their
    meaning). In an Ikaros 2 file a 1-D input with more values than its form needs is
    read for its first values, as Ikaros 2 does (golden files: four values in xyz form
    give the first three), with a warning; one with fewer is an error.

    In an Ikaros 3 file (dialect 3) the output has Ikaros 3's shapes: a pose is a row (one
    pose gives a 1 x width output) and a matrix is size_y x size_x (several poses: n x
    size_y x size_x, a shape the reference does not settle); and, as in Ikaros 3, a
    quaternion input or output is not implemented and the output stays all zero
    (``quaternions="zero"``, the default there; ``quaternions="computed"`` converts them).
    ``turns`` is Ikaros 3's name for ``tau``."""

    input_format = Parameter("xyz", "the form of each input pose", options=_FORMATS)
    output_format = Parameter("xyz", "the form of each output pose", options=_FORMATS)
    angle_unit = Parameter("degrees", "the unit of Euler angles: degrees, radians or tau "
                           "(1 = 360 degrees; turns is the same)",
                           options="degrees/radians/tau/turns")
    quaternions = Parameter("computed", "computed: convert quaternions; zero: a quaternion "
                            "input or output gives all zeros (Ikaros 3, where they are not "
                            "implemented)", options="computed/zero", default_v3="zero")
    size_x = Parameter(4, "columns of the matrix form: 4, or 3 for the rotation alone",
                       type="int", range=(3, 4))
    size_y = Parameter(4, "rows of the matrix form: 4, or 3 without the last row (0 0 0 1)",
                       type="int", range=(3, 4))
    INPUT = Input("one pose, or one pose per row, in input_format")
    OUTPUT = Output("the poses in output_format: 1-D for one pose, else one row per pose")

    def _width(self, fmt: str) -> int:
        return self.size_x * self.size_y if fmt == "matrix" else _WIDTH[fmt]

    def _poses(self, shape):
        """Number of poses in an input of this shape (0: one pose, 1-D), or an error
        message."""
        width = self._width(self.input_format)
        n = int(np.prod(shape))
        block = (self.size_y, self.size_x)
        if self.input_format == "matrix" and tuple(shape[-2:]) == block:
            return 0 if len(shape) == 2 else n // width
        if len(shape) <= 1:
            if n < width or (n > width and self.dialect == "3"):
                return (f"an input in {self.input_format} form needs {width} values, "
                        f"not {n}")
            return 0          # one pose, 1-D
        if shape[-1] != width:
            return (f"each row of an input in {self.input_format} form needs {width} "
                    f"values, not {shape[-1]}")
        return n // width

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape is None:
            return
        poses = self._poses(shape)
        if isinstance(poses, str):
            raise ValueError(poses)
        width = self._width(self.output_format)
        if self.dialect == "3":
            rows = max(poses, 1)
            block = (self.size_y, self.size_x)
            self.set_output_shape("OUTPUT", (block if rows == 1 else (rows,) + block)
                                  if self.output_format == "matrix" else (rows, width))
        else:
            self.set_output_shape("OUTPUT", (width,) if poses == 0 else (poses, width))

    def init(self):
        width = self._width(self.input_format)
        if self.INPUT.ndim <= 1 and self.INPUT.size > width:
            self.warning(f"INPUT has {self.INPUT.size} values and the {self.input_format} "
                         f"form {width}: only the first {width} are used, as in Ikaros 2")
            self._in = self.INPUT.reshape(-1)[:width].reshape(1, width)
        else:
            self._in = self.INPUT.reshape(-1, width)
        self._out = self.OUTPUT.reshape(-1, self._width(self.output_format))
        self._warned = False

    def tick(self):
        if self.quaternions == "zero" and "quaternion" in (self.input_format,
                                                           self.output_format):
            self.OUTPUT[...] = 0
            return
        x = self._in.astype(np.float64)
        n = x.shape[0]
        unit = _TO_RADIANS[self.angle_unit]
        rot = np.broadcast_to(np.eye(3), (n, 3, 3))
        pos = np.zeros((n, 3))
        fmt = self.input_format
        if fmt == "xyz":
            pos = x[:, 0:3]
        elif fmt == "xyzaxayaz":
            pos = x[:, 0:3]
            rot = euler_to_matrices(x[:, 3] * unit, x[:, 4] * unit, x[:, 5] * unit)
        elif fmt == "axayaz":
            rot = euler_to_matrices(x[:, 0] * unit, x[:, 1] * unit, x[:, 2] * unit)
        elif fmt == "matrix":
            m = x.reshape(n, self.size_y, self.size_x)
            rot = m[:, :3, :3]
            if self.size_x == 4:
                pos = m[:, :3, 3]
        else:
            rot, zero = quaternions_to_matrices(x)
            if zero.any() and not self._warned:
                self._warned = True
                self.warning("a zero quaternion has no rotation; it is read as no rotation")

        out = self._out
        fmt = self.output_format
        if fmt == "xyz":
            out[:] = pos
        elif fmt in ("xyzaxayaz", "axayaz"):
            angles = np.stack(matrices_to_euler(rot), axis=-1) / unit
            if fmt == "axayaz":
                out[:] = angles
            else:
                out[:, 0:3] = pos
                out[:, 3:6] = angles
        elif fmt == "matrix":
            m = np.zeros((n, 4, 4))
            m[:, :3, :3] = rot
            m[:, :3, 3] = pos
            m[:, 3, 3] = 1
            out[:] = m[:, :self.size_y, :self.size_x].reshape(n, -1)
        else:
            out[:] = matrices_to_quaternions(rot)
