"""InputCSV: reads a CSV table with a header row, one row per tick."""
from ikaros.module import Module, Parameter, attribute_name

from ._csvnames import csv_delimiter
from ._files import build_error, resolve
from ._tables import RowPlayer, read_csv


class InputCSV(Module):
    """Reads a CSV file such as a spreadsheet saves. The first row is a header of column
    names; every following row holds the values of one tick. Columns are grouped into
    outputs by name: a column ``X`` is an output X of one element; columns ``X[0]``,
    ``X[1]``, ... ``X[n-1]`` form an output X of n elements; ``X[i][j]`` (or ``X[i,j]``)
    form a matrix output X, and more indices give higher ranks. The indices of a group must
    cover every element exactly once, in any column order. A name that is not a valid port
    name has its other characters replaced by ``_`` (``time (s)`` is the output
    ``time__s_``). An empty cell is 0, a row with fewer cells than the header is padded with
    0, and rows with no values are skipped. OutputCSV writes files in this form. The whole
    file is read when the model loads, so errors are reported with their line.

    Row k of the data is output on tick k (the outputs are 0 in init); each row is repeated
    ``repetitions`` times and the table is read ``iterations`` times (0 means forever).
    After the last row the outputs are 0; ``extend`` ticks later the module sends
    end-of-file, which stops the run, unless ``send_end_of_file`` is no."""

    filename = Parameter("", "the CSV file to read; relative to the model file's folder")
    delimiter = Parameter(",", 'the character between values: "," (the default), ";", or '
                          '"tab"')
    iterations = Parameter(1, "how many times the table is read; 0 means forever", type="int")
    repetitions = Parameter(1, "how many ticks each row is output", type="int")
    extend = Parameter(0, "ticks to run after the last row before end-of-file is sent",
                       type="int")
    send_end_of_file = Parameter(True, "send end-of-file (stopping the run) when the data are "
                                 "exhausted; with no, the outputs are 0 forever")

    def configure(self):
        if not self.filename:
            raise build_error(self, "InputCSV needs a filename")
        path = resolve(self, self.filename)
        self._groups, self._data = read_csv(self, path, f"CSV file {self.filename}",
                                            csv_delimiter(self))
        for name, shape, _ in self._groups:
            self.add_output(name, shape, description=f"the columns {name} of the current row")

    def init(self):
        outputs = [(getattr(self, attribute_name(name)).reshape(-1), columns)
                   for name, _, columns in self._groups]
        self._player = RowPlayer(self, self._data, outputs, f'CSV file "{self.filename}"')

    def tick(self):
        self._player.tick()
