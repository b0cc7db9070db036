"""DirectionDetector: global motion from a table of point pairs."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

SMOOTHING = 0.7          # the part of the previous MOTION-VECTOR kept each tick (Ikaros 2)
DRAW_ORIGIN = (0.5, 0.5)


class DirectionDetector(Module):
    """Global visual motion from a table of tracked points, one row each: the first four
    values of a row are a point's position before and after, (x0, y0, x1, y1) (image y
    pointing down); further values in a row are not used. A vector is read as rows of 4.
    As Ikaros 2 computes it (its golden file shows it to the last digit), MOTION-VECTOR
    sums the motions (x1 - x0, y1 - y0) of the rows and adds 0.7 times its previous value,
    so a steady motion m leads to m / 0.3; MOTION-VECTOR-DRAW is the line from (0.5, 0.5)
    along MOTION-VECTOR, (0.5, 0.5, 0.5 + vx, 0.5 + vy). Rows whose motion is longer than
    ``crop`` are left out (crop 0: none are), and NO-OF-ROWS, when connected and at least 1,
    limits the table to its first rows (the golden case, with NO-OF-ROWS 0.7, sums every
    row).

    The rest is this project's reading, not Ikaros 2's computation: MOTION-DIRECTION is
    one-hot over (left, right, up, down), the larger component of MOTION-VECTOR deciding
    (which the golden case, a motion mostly to the right giving (0, 1, 0, 0), agrees with);
    LOOMING is the mean speed of the points away from their centroid (positive when the
    image expands); LEFT-FIELD-MOTION and RIGHT-FIELD-MOTION add up the lengths of the
    motions of the points left and right of the centroid. In Ikaros 2's golden case (an 8 x
    8 table) LOOMING is 0 and the two fields add the lengths of rows 0-1 and rows 2-3 only,
    a choice of rows that one case does not explain; this class gives other values
    there."""

    no_of_directions = Parameter(8, "the number of directions of the original (not used: "
                                 "MOTION-DIRECTION has four)", type="int")
    crop = Parameter(0.0, "motions longer than this are left out; 0: none are")
    INPUT = Input("the table of point pairs, rows (x0, y0, x1, y1, ...)")
    NO_OF_ROWS = Input("how many rows of INPUT are used (below 1 or unconnected: all)",
                       optional=True, name="NO-OF-ROWS")
    MOTION_VECTOR = Output("the summed motion (dx, dy), plus 0.7 times its previous value",
                           size="2", name="MOTION-VECTOR")
    MOTION_DIRECTION = Output("one-hot: left, right, up, down", size="4",
                              name="MOTION-DIRECTION")
    LOOMING = Output("mean speed away from the points' centroid", size="1")
    LEFT_FIELD_MOTION = Output("summed length of the motions left of the centroid", size="1",
                               name="LEFT-FIELD-MOTION")
    RIGHT_FIELD_MOTION = Output("summed length of the motions right of the centroid",
                                size="1", name="RIGHT-FIELD-MOTION")
    MOTION_VECTOR_DRAW = Output("a line (0.5, 0.5, 0.5 + vx, 0.5 + vy) along MOTION-VECTOR",
                                size="4", name="MOTION-VECTOR-DRAW")

    def init(self):
        shape = self.INPUT.shape
        if len(shape) >= 2 and shape[-1] >= 4:
            self._table = self.INPUT.reshape(-1, shape[-1])[:, :4]
        elif self.INPUT.size % 4 == 0:
            self._table = self.INPUT.reshape(-1, 4)
        else:
            raise ValueError(f"INPUT must have rows of at least 4 values (x0, y0, x1, y1), "
                             f"not shape {shape}")
        self._vector = np.zeros(2)

    def tick(self):
        table = np.asarray(self._table, np.float64)
        if self.NO_OF_ROWS is not None and self.NO_OF_ROWS.flat[0] >= 1:
            table = table[:int(self.NO_OF_ROWS.flat[0])]
        points, motions = table[:, :2], table[:, 2:] - table[:, :2]
        if self.crop > 0:
            keep = np.hypot(motions[:, 0], motions[:, 1]) <= self.crop
            points, motions = points[keep], motions[keep]
        self._vector = SMOOTHING * self._vector + motions.sum(axis=0)
        vx, vy = self._vector
        self.MOTION_VECTOR[...] = self._vector
        self.MOTION_VECTOR_DRAW[...] = (*DRAW_ORIGIN, DRAW_ORIGIN[0] + vx, DRAW_ORIGIN[1] + vy)
        self.MOTION_DIRECTION.fill(0)
        if vx or vy:
            self.MOTION_DIRECTION[(0 if vx < 0 else 1) if abs(vx) >= abs(vy)
                                  else (2 if vy < 0 else 3)] = 1
        for out in (self.LOOMING, self.LEFT_FIELD_MOTION, self.RIGHT_FIELD_MOTION):
            out.fill(0)
        if len(points) == 0:
            return
        offsets = points - points.mean(axis=0)
        distance = np.hypot(offsets[:, 0], offsets[:, 1])
        away = distance > 0
        if away.any():
            self.LOOMING[0] = ((offsets[away] * motions[away]).sum(axis=1)
                               / distance[away]).mean()
        lengths = np.hypot(motions[:, 0], motions[:, 1])
        self.LEFT_FIELD_MOTION[0] = lengths[offsets[:, 0] < 0].sum()
        self.RIGHT_FIELD_MOTION[0] = lengths[offsets[:, 0] > 0].sum()
