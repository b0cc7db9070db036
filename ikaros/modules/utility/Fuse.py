"""Fuse: merges streams of homogeneous matrices with object and frame ids."""
import numpy as np

from ikaros.module import Module, Output, Parameter


class Fuse(Module):
    """Merges ``no_of_inputs`` streams of coordinate transformations into one table. Stream k
    has three inputs: MATRIX_k, a table of 4 x 4 homogeneous matrices, one per row as 16
    values in row order (any shape with a multiple of 16 elements is read that way), and
    OBJECT_ID_k and FRAME_ID_k, the object each matrix describes and the frame of reference
    it is given in, one value per matrix. A matrix is valid when its last element (bottom
    right) is above 0.1; invalid ones are skipped. The valid matrices of all streams that
    share both an object id and a frame id are averaged into one, whose 3 x 3 rotation part
    is then replaced by the nearest rotation matrix (through a singular value
    decomposition, keeping the determinant +1). The fused entries are written to the first
    rows of MATRIX, OBJECT_ID and FRAME_ID, sorted by object id and then frame id; the
    remaining rows are 0 (and so invalid). The outputs have as many rows as all streams
    together. The reference says only that the original combines the entries with the same
    object and frame ids (no golden file holds Fuse): the averaging, the nearest rotation
    and the order of the rows are this project's reading."""

    no_of_inputs = Parameter(2, "number of streams: inputs MATRIX_k, OBJECT_ID_k and "
                             "FRAME_ID_k for k = 1 .. no_of_inputs", type="int")
    MATRIX = Output("the fused matrices, one per row as 16 values; unused rows are 0")
    OBJECT_ID = Output("the object id of each row of MATRIX; 0 for unused rows")
    FRAME_ID = Output("the frame id of each row of MATRIX; 0 for unused rows")

    def configure(self):
        if self.no_of_inputs < 1:
            raise ValueError(f"no_of_inputs must be at least 1, not {self.no_of_inputs}")
        for k in range(1, self.no_of_inputs + 1):
            self.add_input(f"MATRIX_{k}", description=f"the matrices of stream {k}, one per "
                           "row as 16 values")
            self.add_input(f"OBJECT_ID_{k}", description=f"the object id of each matrix of "
                           f"stream {k}")
            self.add_input(f"FRAME_ID_{k}", description=f"the frame id of each matrix of "
                           f"stream {k}")

    def set_sizes(self):
        total = 0
        for k in range(1, self.no_of_inputs + 1):
            shape = self.input_shape(f"MATRIX_{k}")
            if shape is None:
                return
            size = int(np.prod(shape))
            if size % 16:
                raise ValueError(f"MATRIX_{k} has {size} elements, not a multiple of 16")
            total += size // 16
        self.set_output_shape("MATRIX", (total, 16))
        self.set_output_shape("OBJECT_ID", (total,))
        self.set_output_shape("FRAME_ID", (total,))

    def init(self):
        self._streams = []
        for k in range(1, self.no_of_inputs + 1):
            m = getattr(self, f"MATRIX_{k}")
            n = m.size // 16
            ids = [getattr(self, f"{name}_{k}") for name in ("OBJECT_ID", "FRAME_ID")]
            for name, ids_k in zip(("OBJECT_ID", "FRAME_ID"), ids):
                if ids_k.size < n:
                    self.fatal_error(f"{name}_{k} has {ids_k.size} elements but MATRIX_{k} "
                                     f"holds {n} matrices")
                    return
            self._streams.append((m, ids[0], ids[1], n))
        self._clear()

    def _clear(self, first=0):
        self.MATRIX[first:] = 0
        self.OBJECT_ID[first:] = 0
        self.FRAME_ID[first:] = 0

    def tick(self):
        matrices = np.concatenate([m.reshape(-1, 16) for m, _, _, _ in self._streams])
        objects = np.concatenate([o.reshape(-1)[:n] for _, o, _, n in self._streams])
        frames = np.concatenate([f.reshape(-1)[:n] for _, _, f, n in self._streams])
        valid = (matrices[:, 15] > 0.1) & np.all(np.isfinite(matrices), axis=1) & \
            np.isfinite(objects) & np.isfinite(frames)
        if not np.any(valid):
            self._clear()
            return
        keys, group = np.unique(np.stack([objects[valid], frames[valid]], axis=1),
                                axis=0, return_inverse=True)
        group = group.reshape(-1)
        sums = np.zeros((len(keys), 16))
        np.add.at(sums, group, matrices[valid].astype(np.float64))
        mean = sums / np.bincount(group, minlength=len(keys))[:, None]
        h = mean.reshape(-1, 4, 4)
        u, _, vt = np.linalg.svd(h[:, :3, :3])
        sign = np.sign(np.linalg.det(u @ vt))
        sign[sign == 0] = 1
        u[:, :, 2] *= sign[:, None]
        h[:, :3, :3] = u @ vt
        g = len(keys)
        self.MATRIX[:g] = h.reshape(g, 16)
        self.OBJECT_ID[:g] = keys[:, 0]
        self.FRAME_ID[:g] = keys[:, 1]
        self._clear(g)
