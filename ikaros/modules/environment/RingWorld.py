"""RingWorld: a circular world of stimuli seen through a retina centred on the gaze
(Ikaros 3)."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter


def _round_half_away(x: float) -> int:
    return int(math.floor(abs(x) + 0.5)) * (1 if x >= 0 else -1)


class RingWorld(Module):
    """A one-dimensional circular world. Each row of STIMULI is a stimulus: angle (degrees),
    reward, punishment, intensity, then C ≥ 1 components. The direction of each stimulus
    relative to the gaze (GAZE[0], 0 when unconnected) is wrapped into [−180, 180). The
    stimulus closest to the gaze within ``fixation_margin`` degrees (the first on a tie) is
    fixated: REWARD and PUNISHMENT are its values and FOVEA its components times its
    intensity (all 0 when none is). Every stimulus within ``field_of_view``/2 of the gaze
    is seen on the retina, at column round((δ + half)/(2·half)·(retina_width − 1)) (halves
    away from zero; column 0 with a retina of width 1): each component cell is the largest
    of intensity × component over the stimuli there (cells start at 0). DISTAL_STIMULI (the
    same columns) fill DISTAL_RETINA alike, and AUDITORY_STIMULI (rows angle, intensity)
    fill AUDITORY_MAP with their intensities; both only when connected. TRACKING is
    accepted but not used, as in Ikaros 3. New in Ikaros 3."""

    field_of_view = Parameter(120.0, "the width of the retina's view (degrees, 0 < f ≤ 360)")
    fixation_margin = Parameter(4.0, "how close to the gaze a stimulus is fixated (degrees, "
                                "0 ... 180)", range=(0, 180))
    retina_width = Parameter(25, "the number of retina columns", type="int", range=(1, None))
    STIMULI = Input("one stimulus per row: angle, reward, punishment, intensity, components")
    AUDITORY_STIMULI = Input("one sound per row: angle, intensity", optional=True)
    DISTAL_STIMULI = Input("distal stimuli, with the columns of STIMULI", optional=True)
    GAZE = Input("the gaze direction (degrees)", optional=True, flatten=True)
    TRACKING = Input("accepted but not used, as in Ikaros 3", optional=True, flatten=True)
    FOVEA = Output("the fixated stimulus's components times its intensity")
    REWARD = Output("the fixated stimulus's reward", size="1")
    PUNISHMENT = Output("the fixated stimulus's punishment", size="1")
    RETINA = Output("components × retina columns")
    DISTAL_RETINA = Output("components × retina columns, of the distal stimuli")
    AUDITORY_MAP = Output("1 × retina columns: the intensity of the sounds", shape="1, "
                          "@retina_width")

    def set_sizes(self):
        shape = self.input_shape("STIMULI")
        if shape is None:
            return
        if len(shape) != 2 or shape[1] < 5:
            raise ValueError(f"STIMULI must have rows of angle, reward, punishment, intensity "
                             f"and at least one component; its shape is {shape}")
        c = shape[1] - 4
        self.set_output_shape("FOVEA", c)
        self.set_output_shape("RETINA", (c, self.retina_width))
        self.set_output_shape("DISTAL_RETINA", (c, self.retina_width))

    def init(self):
        if not 0 < self.field_of_view <= 360:
            self.fatal_error(f"field_of_view must be above 0 and at most 360, not "
                             f"{self.field_of_view}")
        for name, columns in (("DISTAL_STIMULI", self.STIMULI.shape[1]),
                              ("AUDITORY_STIMULI", 2)):
            x = getattr(self, name)
            if x is not None and (x.ndim != 2 or x.shape[1] != columns):
                self.fatal_error(f"{name} must have rows of {columns} columns; its shape is "
                                 f"{x.shape}")
        for name in ("GAZE", "TRACKING"):
            x = getattr(self, name)
            if x is not None and x.size != 1:
                self.fatal_error(f"{name} must have one element, not {x.size}")

    def _delta(self, angle: float, gaze: float) -> float:
        d = math.fmod(angle - gaze + 180.0, 360.0)
        return (d + 360.0 if d < 0 else d) - 180.0

    def _column(self, delta: float) -> int:
        if self.retina_width == 1:
            return 0
        half = self.field_of_view / 2
        column = _round_half_away((delta + half) / (2 * half) * (self.retina_width - 1))
        return min(max(column, 0), self.retina_width - 1)

    def _map(self, rows, gaze, out, value) -> None:
        """Writes value(row) into the column of each row in view (keeping the largest)."""
        half = self.field_of_view / 2
        for row in rows:
            delta = self._delta(float(row[0]), gaze)
            if abs(delta) <= half:
                column = self._column(delta)
                out[:, column] = np.maximum(out[:, column], value(row))

    def tick(self):
        for out in (self.FOVEA, self.REWARD, self.PUNISHMENT, self.RETINA,
                    self.DISTAL_RETINA, self.AUDITORY_MAP):
            out[...] = 0
        gaze = float(self.GAZE[0]) if self.GAZE is not None else 0.0
        best, best_distance = None, None
        for row in self.STIMULI:
            distance = abs(self._delta(float(row[0]), gaze))
            if distance <= self.fixation_margin and (best is None or distance < best_distance):
                best, best_distance = row, distance
        if best is not None:
            self.REWARD[0], self.PUNISHMENT[0] = best[1], best[2]
            self.FOVEA[...] = best[3] * best[4:]
        self._map(self.STIMULI, gaze, self.RETINA, lambda row: row[3] * row[4:])
        if self.DISTAL_STIMULI is not None:
            self._map(self.DISTAL_STIMULI, gaze, self.DISTAL_RETINA,
                      lambda row: row[3] * row[4:])
        if self.AUDITORY_STIMULI is not None:
            self._map(self.AUDITORY_STIMULI, gaze, self.AUDITORY_MAP, lambda row: row[1:2])
