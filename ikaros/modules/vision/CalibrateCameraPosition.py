"""CalibrateCameraPosition: the camera's pose from a marker at a known place."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._markers import ROW_ID, ROW_LENGTH, ROW_MATRIX


class CalibrateCameraPosition(Module):
    """Computes where the camera is from a marker whose pose in the world is known: INPUT is
    MarkerTracker's MARKERS table, and when the marker with id `marker_number` is in it, the
    camera's pose in the world is marker_position · (the marker's pose seen from the
    camera)⁻¹. The pose is printed the first time it is found and is on CAMERA every tick
    the marker is seen (the last one is kept otherwise). With ArUco markers, marker_number
    is an id of MarkerTracker's dictionary (Ikaros 2's default, 1218, was an ARToolKitPlus
    BCH id)."""

    marker_number = Parameter(1218, "the id of the marker at a known place", type="int")
    marker_position = Parameter("1 0 0 500; 0 1 0 100; 0 0 1 0; 0 0 0 1",
                                "the marker's pose in the world, a 4 x 4 matrix",
                                type="matrix")
    INPUT = Input("MarkerTracker's MARKERS table (rows of 28 values)")
    CAMERA = Output("the camera's pose in the world, 4 x 4 (identity until the marker is "
                    "seen)", shape="4, 4")
    FOUND = Output("1 on ticks when the marker is seen, otherwise 0", size="1")

    def init(self):
        if self.INPUT.size % ROW_LENGTH:
            raise ValueError(f"INPUT must be a marker table with rows of {ROW_LENGTH} "
                             f"values, not shape {self.INPUT.shape}")
        world = np.asarray(self.marker_position, np.float64)
        if world.size != 16:
            raise ValueError(f"marker_position must be a 4 x 4 matrix, not {world.shape}")
        self._world = world.reshape(4, 4)
        self._table = self.INPUT.reshape(-1, ROW_LENGTH)
        self._reported = False
        self.CAMERA[...] = np.eye(4)

    def tick(self):
        rows = self._table[(self._table[:, ROW_ID] == self.marker_number) &
                           (self._table[:, 1] > 0)]
        self.FOUND[0] = float(len(rows) > 0)
        if not len(rows):
            return
        seen = rows[0, ROW_MATRIX:ROW_LENGTH].astype(np.float64).reshape(4, 4)
        self.CAMERA[...] = self._world @ np.linalg.inv(seen)
        if not self._reported:
            self._reported = True
            text = "; ".join(" ".join(f"{v:.1f}" for v in row) for row in self.CAMERA)
            self.print(f"camera position from marker {self.marker_number}: {text}")
