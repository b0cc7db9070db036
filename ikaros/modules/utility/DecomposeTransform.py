"""DecomposeTransform: translation, rotation and scale of homogeneous matrices."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class DecomposeTransform(Module):
    """Splits 4x4 homogeneous transformation matrices into translation, rotation and scale.
    The input holds one or more matrices of 16 elements each, row by row (a 1x16n row as in
    Ikaros 2, or n x 16, or n x 4 x 4); row i of each output belongs to matrix i. The matrix
    is read as M = T R S. TRANSLATION is the last column (x, y, z). As Ikaros 2 computes it
    (golden files), the default: SCALE is the diagonal M[0,0], M[1,1], M[2,2] (the scale
    only when there is no rotation), and ROTATION the Euler angles (x, y, z) of R = Rz(z)
    Ry(y) Rx(x) taken from the matrix with its scale left in, in radians whatever
    ``use_degrees`` says. The golden files show a rotation about z and a pure scale; how
    the original's angles come out for a matrix with both scale and rotation is this
    project's reading. ``decomposition="corrected"`` (this project's): SCALE is the
    lengths of the first three columns, the angles are taken after the scale is divided
    out, and they are in degrees when ``use_degrees`` is set. At gimbal lock (y = +-90
    degrees) x is 0."""

    use_degrees = Parameter(True, "give the rotation in degrees (with decomposition="
                            "corrected; Ikaros 2 always gives radians)")
    decomposition = Parameter("original", "original: as Ikaros 2 (the diagonal as scale, "
                              "radians); corrected: column lengths, the scale divided out, "
                              "use_degrees", options="original/corrected")
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
        corrected = self.decomposition == "corrected"
        if corrected:
            scale = np.sqrt(np.sum(m[:, :3, :3] ** 2, axis=1))          # column lengths
            safe = np.where(scale == 0, 1.0, scale)
            r = m[:, :3, :3] / safe[:, None, :]
        else:
            scale = np.diagonal(m[:, :3, :3], axis1=1, axis2=2)
            r = m[:, :3, :3]
        self.SCALE[...] = scale
        s = np.clip(-r[:, 2, 0], -1.0, 1.0)
        y = np.arcsin(s)
        locked = np.abs(r[:, 2, 0]) >= 1.0 - 1e-7
        x = np.where(locked, 0.0, np.arctan2(r[:, 2, 1], r[:, 2, 2]))
        z = np.where(locked, np.arctan2(-r[:, 0, 1], r[:, 1, 1]),
                     np.arctan2(r[:, 1, 0], r[:, 0, 0]))
        angles = np.stack([x, y, z], axis=1) + 0.0          # no -0
        if self.use_degrees and corrected:
            angles = np.degrees(angles)
        self.ROTATION[...] = angles
        if self.debug:
            self.print(f"translation {self.TRANSLATION.tolist()} rotation "
                       f"{self.ROTATION.tolist()} scale {self.SCALE.tolist()}")
