"""Transform: re-expresses homogeneous matrices in other reference frames."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Transform(Module):
    """Combines two lists of 4 x 4 homogeneous transformation matrices. Each row of MATRIX_1
    and MATRIX_2 holds one matrix as 16 elements, row by row (a (n, 4, 4) input works too);
    OBJECT_ID_x and FRAME_ID_x give, for each row, the id of the object it places and of the
    reference frame it is expressed in. A matrix is used only when it is valid, that is, its
    last element is above 0.1 (rows of zeros mark unused entries). With ``invert_1`` (or
    ``invert_2``) the matrices of that list are inverted before use, which swaps the roles of
    their object and frame ids. For every pair (i, j), in the order of i and then j, whose
    object id in list 1 equals the frame id in list 2, the product M1[i] @ M2[j] is output: it
    places object 2 (OBJECT_ID is list 2's object id) in list 1's frame (FRAME_ID is list 1's
    frame id). The outputs have
    as many rows as the longer input list; rows after the last match are 0. Matches beyond
    that are left out, with a warning the first time (Ikaros 2 wrote past its outputs), and
    a matrix that cannot be inverted counts as invalid."""

    invert_1 = Parameter(False, "invert the matrices of MATRIX_1 before use")
    invert_2 = Parameter(False, "invert the matrices of MATRIX_2 before use")
    MATRIX_1 = Input("the first list of matrices, one 4 x 4 matrix (16 elements) per row")
    OBJECT_ID_1 = Input("the object id of each matrix in MATRIX_1")
    FRAME_ID_1 = Input("the id of the reference frame of each matrix in MATRIX_1")
    MATRIX_2 = Input("the second list of matrices, one 4 x 4 matrix (16 elements) per row")
    OBJECT_ID_2 = Input("the object id of each matrix in MATRIX_2")
    FRAME_ID_2 = Input("the id of the reference frame of each matrix in MATRIX_2")
    MATRIX = Output("the products, one 4 x 4 matrix (16 elements) per row")
    OBJECT_ID = Output("the object id of each row of MATRIX")
    FRAME_ID = Output("the id of the reference frame of each row of MATRIX")

    def set_sizes(self):
        s1, s2 = self.input_shape("MATRIX_1"), self.input_shape("MATRIX_2")
        if s1 is None or s2 is None:
            return
        n = max(int(np.prod(s1)) // 16, int(np.prod(s2)) // 16, 1)
        self.set_output_shape("MATRIX", (n, 16))
        self.set_output_shape("OBJECT_ID", (n,))
        self.set_output_shape("FRAME_ID", (n,))

    def init(self):
        self._lists = []
        for k in ("1", "2"):
            m = getattr(self, "MATRIX_" + k)
            if m.size % 16 or m.size == 0:
                if self.dialect == "3":
                    self.fatal_error(f"MATRIX_{k} must hold 4 x 4 matrices of 16 elements "
                                     f"each; it has shape {m.shape}")
                    return
                self.warning(f"MATRIX_{k} has {m.size} elements, not a multiple of 16: as in "
                             f"Ikaros 2 only its {m.size // 16} whole matrices are used")
            n = m.size // 16
            obj, frame = getattr(self, "OBJECT_ID_" + k), getattr(self, "FRAME_ID_" + k)
            for name, ids in (("OBJECT_ID_", obj), ("FRAME_ID_", frame)):
                if ids.size < n:
                    self.fatal_error(f"{name}{k} has {ids.size} elements; MATRIX_{k} has {n} "
                                     f"matrices")
                    return
            self._lists.append((m.reshape(-1)[:16 * n].reshape(n, 4, 4), obj.reshape(-1)[:n],
                                frame.reshape(-1)[:n]))
        self._out = self.MATRIX.reshape(-1, 4, 4)
        self._warned = False

    @staticmethod
    def _prepare(m, obj, frame, invert):
        """The matrices to multiply, their valid flags, and (object, frame) ids."""
        valid = m[:, 3, 3] > 0.1
        if not invert:
            return m.astype(np.float64), valid, obj, frame
        inverted = np.zeros(m.shape, dtype=np.float64)
        invertible = np.abs(np.linalg.det(m.astype(np.float64))) > 1e-12
        ok = valid & invertible
        if ok.any():
            inverted[ok] = np.linalg.inv(m[ok].astype(np.float64))
        return inverted, ok, frame, obj

    def tick(self):
        self._out.fill(0)
        self.OBJECT_ID.fill(0)
        self.FRAME_ID.fill(0)
        (m1, o1, f1), (m2, o2, f2) = self._lists
        a, valid_a, obj_a, frame_a = self._prepare(m1, o1, f1, self.invert_1)
        b, valid_b, obj_b, frame_b = self._prepare(m2, o2, f2, self.invert_2)
        match = valid_a[:, None] & valid_b[None, :] & (obj_a[:, None] == frame_b[None, :])
        i, j = np.nonzero(match)            # row-major: in the order of i, then j
        capacity = self._out.shape[0]
        if i.size > capacity:
            if not self._warned:
                self._warned = True
                self.warning(f"{i.size} matching pairs but room for {capacity}; the rest "
                             f"are left out")
            i, j = i[:capacity], j[:capacity]
        k = i.size
        if k:
            self._out[:k] = np.matmul(a[i], b[j])
            self.OBJECT_ID[:k] = obj_b[j]
            self.FRAME_ID[:k] = frame_a[i]
