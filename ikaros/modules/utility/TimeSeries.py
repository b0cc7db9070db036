"""TimeSeries: plays the rows of a matrix one after another (Ikaros 3)."""
import numpy as np

from ikaros.module import Module, Output, Parameter


class TimeSeries(Module):
    """Outputs the rows of ``data`` in order, each for ``base_duration`` seconds (times its
    multiplier in column 0 when ``first_column_duration`` is set; a multiplier <= 0 counts
    as 1). Each tick the current row is written first; then tick_duration is added to the
    elapsed time, and while it reaches the row's duration the row advances and TRIG is 1
    for this tick (the new row shows from the next tick). After the last row the series
    starts again with ``loop``, else the last row is held with no TRIG. A 1-D ``data`` is
    output as it is. A base_duration <= 0 holds the current row. Reset of the state does
    not restart the series (as in Ikaros 3). New in Ikaros 3."""

    data = Parameter("1, 2, 3; 4, 5, 6; 7, 8, 9", "one sample per row", type="matrix")
    base_duration = Parameter(1.0, "seconds that a row of multiplier 1 lasts")
    loop = Parameter(False, "start again from the first row after the last")
    first_column_duration = Parameter(False, "column 0 of each row is that row's duration "
                                      "multiplier, not output")
    OUTPUT = Output("the current row (without column 0 with first_column_duration)")
    TRIG = Output("1 on a tick when the series advances to the next row, else 0", size="1")

    def configure(self):
        cols = np.shape(self.data)[-1] if np.size(self.data) else 0
        self.set_output_shape("OUTPUT", max(0, cols - int(bool(self.first_column_duration))))

    def init(self):
        self._position = 0.0
        self._index = 0
        self.TRIG[0] = 0
        self._write_row()

    def _write_row(self):
        data = self.data
        if data.ndim < 2:
            row = data.reshape(-1)
        else:
            row = data[self._index, 1:] if self.first_column_duration else data[self._index]
        n = min(self.OUTPUT.size, row.size)
        self.OUTPUT[:n] = row[:n]

    def _duration(self):
        if self.first_column_duration and self.data[self._index, 0] > 0:
            return self.base_duration * float(self.data[self._index, 0])
        return self.base_duration

    def tick(self):
        self.TRIG[0] = 0
        data = self.data
        if data.size == 0:
            return
        self._write_row()
        if data.ndim < 2 or self.base_duration <= 0:
            return
        rows = data.shape[0]
        self._position += self.clock.tick_duration
        while self._position >= self._duration():
            self._position -= self._duration()
            self._index += 1
            if self.loop:
                self._index %= rows
            elif self._index >= rows:
                self._index, self._position = rows - 1, 0.0
                break
            self.TRIG[0] = 1
