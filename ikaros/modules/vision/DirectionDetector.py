"""DirectionDetector: global motion from a table of flow vectors."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class DirectionDetector(Module):
    """Global visual motion from a flow table such as BlockMatching's FLOW: one row
    (x, y, dx, dy) per point, in pixels (image y pointing down), of which the first
    NO-OF-ROWS are used (all when it is not connected). Rows whose vector is longer than
    `crop` pixels are ignored as mismatches (crop 0: none are). MOTION-VECTOR is the mean
    (dx, dy). MOTION-DIRECTION is (sector, angle, magnitude, count): the mean vector's angle
    in radians counter-clockwise from the right with y up, the sector it falls in when the
    circle is cut into `no_of_directions` sectors centred on 0 (0 = right), its length and
    the number of rows used. LOOMING is the mean speed away from the centroid of the points
    (positive when the image expands, as when something approaches). LEFT-FIELD-MOTION and
    RIGHT-FIELD-MOTION are the mean dx of the points left and right of the centroid.
    MOTION-VECTOR-DRAW is a line (x0, y0, x1, y1) from the centroid along the mean vector.
    All of this is this project's reading of the reference's one sentence, and it is not
    Ikaros 2's computation: its one golden case (an 8 x 8 INPUT) reads each row as
    (x0, y0, x1, y1), sums (x1 - x0, y1 - y0) over all rows into MOTION-VECTOR with the
    previous tick's value times 0.7 added, draws MOTION-VECTOR-DRAW from (0.5, 0.5), and
    gives left and right field motions that one case does not explain; this module does
    not reproduce it."""

    no_of_directions = Parameter(8, "sectors the direction is quantised to", type="int")
    crop = Parameter(0.0, "vectors longer than this (pixels) are ignored; 0: none")
    INPUT = Input("the flow table, rows (x, y, dx, dy)")
    NO_OF_ROWS = Input("how many rows of INPUT are used (default: all)", optional=True,
                       name="NO-OF-ROWS")
    MOTION_VECTOR = Output("the mean motion (dx, dy)", size="2", name="MOTION-VECTOR")
    MOTION_DIRECTION = Output("(sector, angle, magnitude, count) of the mean motion",
                              size="4", name="MOTION-DIRECTION")
    LOOMING = Output("mean speed away from the points' centroid", size="1")
    LEFT_FIELD_MOTION = Output("mean dx of the points left of the centroid", size="1",
                               name="LEFT-FIELD-MOTION")
    RIGHT_FIELD_MOTION = Output("mean dx of the points right of the centroid", size="1",
                                name="RIGHT-FIELD-MOTION")
    MOTION_VECTOR_DRAW = Output("a line (x0, y0, x1, y1) from the centroid along the mean "
                                "motion", size="4", name="MOTION-VECTOR-DRAW")

    def init(self):
        if self.INPUT.size % 4:
            raise ValueError(f"INPUT must have rows (x, y, dx, dy), not shape "
                             f"{self.INPUT.shape}")
        if self.no_of_directions < 1:
            raise ValueError("no_of_directions must be at least 1")
        self._table = self.INPUT.reshape(-1, 4)

    def tick(self):
        table = self._table
        if self.NO_OF_ROWS is not None:
            table = table[:max(0, int(self.NO_OF_ROWS.flat[0]))]
        points, vectors = table[:, :2], table[:, 2:]
        if self.crop > 0:
            keep = np.hypot(vectors[:, 0], vectors[:, 1]) <= self.crop
            points, vectors = points[keep], vectors[keep]
        outputs = (self.MOTION_VECTOR, self.MOTION_DIRECTION, self.LOOMING,
                   self.LEFT_FIELD_MOTION, self.RIGHT_FIELD_MOTION, self.MOTION_VECTOR_DRAW)
        for out in outputs:
            out.fill(0)
        if len(points) == 0:
            return
        mean = vectors.mean(axis=0)
        centre = points.mean(axis=0)
        angle = float(np.arctan2(-mean[1], mean[0])) % (2 * np.pi)
        step = 2 * np.pi / self.no_of_directions
        sector = int(np.floor(angle / step + 0.5)) % self.no_of_directions
        self.MOTION_VECTOR[...] = mean
        self.MOTION_DIRECTION[...] = (sector, angle, np.hypot(*mean), len(points))
        offsets = points - centre
        distance = np.hypot(offsets[:, 0], offsets[:, 1])
        away = distance > 0
        if away.any():
            radial = (offsets[away] * vectors[away]).sum(axis=1) / distance[away]
            self.LOOMING[0] = radial.mean()
        left, right = offsets[:, 0] < 0, offsets[:, 0] > 0
        if left.any():
            self.LEFT_FIELD_MOTION[0] = vectors[left, 0].mean()
        if right.any():
            self.RIGHT_FIELD_MOTION[0] = vectors[right, 0].mean()
        self.MOTION_VECTOR_DRAW[...] = (*centre, *(centre + mean))
