"""DecomposeTransform: translation, rotation and scale of homogeneous matrices."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class DecomposeTransform(Module):
    """Splits 4x4 homogeneous transformation matrices into translation, rotation and scale.
    The input holds one or more matrices of 16 elements each, row by row (a 1x16n row as in
    Ikaros 2, or n x 16, or n x 4 x 4); row i of each output belongs to matrix i. The matrix
    is read as M = T R S: TRANSLATION is the last column (x, y, z), SCALE the lengths of the
    first three columns, and ROTATION the Euler angles (x, y, z) of R = Rz(z) Ry(y) Rx(x)
    after the scale is divided out, in degrees when ``use_degrees`` is set (the original
    ignored use_degrees and always gave radians; it also left the scale in the matrix when
    it took the angles). At gimbal lock (y = +-90 degrees) x is 0."""

    use_degrees = Parameter(True, "give the rotation in degrees (otherwise in radians)")
    debug = Parameter(False, "print the outputs on every tick")
    INPUT = Input("the matrices, 16 elements each, row by row")
    TRANSLATION = Output("the translation (x, y, z) of each matrix, one row per matrix")
    ROTATION = Output("the Euler angles (x, y, z) of each matrix, one row per matrix")
    SCALE = Output("the scale along x, y and z of each matrix, one row per matrix")

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape is None:
            return
        n = math.prod(shape)
        if n == 0 or n % 16:
            raise ValueError(f"the input must hold 4x4 matrices (a multiple of 16 elements), "
                             f"not {n} elements")
        for name in ("TRANSLATION", "ROTATION", "SCALE"):
            self.set_output_shape(name, (n // 16, 3))

    def init(self):
        self._m = self.INPUT.reshape(-1, 4, 4)

    def tick(self):
        m = self._m.astype(np.float64)
        self.TRANSLATION[...] = m[:, :3, 3]
        scale = np.sqrt(np.sum(m[:, :3, :3] ** 2, axis=1))          # column lengths
        self.SCALE[...] = scale
        safe = np.where(scale == 0, 1.0, scale)
        r = m[:, :3, :3] / safe[:, None, :]
        s = np.clip(-r[:, 2, 0], -1.0, 1.0)
        y = np.arcsin(s)
        locked = np.abs(r[:, 2, 0]) >= 1.0 - 1e-7
        x = np.where(locked, 0.0, np.arctan2(r[:, 2, 1], r[:, 2, 2]))
        z = np.where(locked, np.arctan2(-r[:, 0, 1], r[:, 1, 1]),
                     np.arctan2(r[:, 1, 0], r[:, 0, 0]))
        angles = np.stack([x, y, z], axis=1) + 0.0          # no -0
        if self.use_degrees:
            angles = np.degrees(angles)
        self.ROTATION[...] = angles
        if self.debug:
            self.print(f"translation {self.TRANSLATION.tolist()} rotation "
                       f"{self.ROTATION.tolist()} scale {self.SCALE.tolist()}")
