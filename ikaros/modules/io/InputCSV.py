"""InputCSV: reads a CSV table with a header row, one row per tick."""
import csv

import numpy as np

from ikaros.module import Module, Parameter, attribute_name

from ._csvnames import csv_delimiter, parse_column, port_name
from ._files import build_error, resolve


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
        delimiter = csv_delimiter(self)
        try:
            with open(path, encoding="utf-8-sig", newline="") as f:
                rows = list(enumerate(csv.reader(f, delimiter=delimiter), 1))
        except OSError as e:
            raise build_error(self, f'cannot read CSV file "{self.filename}": '
                              f'{e.strerror}') from None
        except (UnicodeDecodeError, csv.Error) as e:
            raise build_error(self, f'cannot read CSV file "{self.filename}": {e}') from None
        rows = [(n, r) for n, r in rows if any(cell.strip() for cell in r)]
        if not rows:
            raise build_error(self, f'CSV file "{self.filename}" is empty')
        header_line, header = rows[0]
        self._groups = self._group_columns(path, header_line, header)
        width = len(header)
        data = np.zeros((len(rows) - 1, width), dtype=np.float32)
        for r, (line, cells) in enumerate(rows[1:]):
            if len(cells) > width:
                raise build_error(self, f"{path}:{line}: {len(cells)} values but the header "
                                  f"has {width} columns")
            for c, cell in enumerate(cells):
                cell = cell.strip()
                if cell:
                    try:
                        data[r, c] = float(cell)
                    except ValueError:
                        raise build_error(self, f'{path}:{line}: "{cell}" in column '
                                          f'"{header[c]}" is not a number') from None
        self._data = data
        for name, shape, _ in self._groups:
            self.add_output(name, shape, description=f"the columns {name} of the current row")

    def _group_columns(self, path, line, header):
        def fail(message):
            return build_error(self, f"{path}:{line}: {message}")
        try:
            parsed = [parse_column(cell) for cell in header]
        except ValueError as e:
            raise fail(str(e)) from None
        if all(_is_number(cell) for cell in header):
            raise fail("the first row must be a header of column names")
        groups: dict[str, list] = {}
        for column, (base, index) in enumerate(parsed):
            groups.setdefault(port_name(base), []).append((index, column))
        result = []
        for name, members in groups.items():
            ranks = {len(index) for index, _ in members}
            if len(ranks) > 1:
                raise fail(f'the columns of "{name}" mix names with different numbers of '
                           f'indices')
            rank = ranks.pop()
            if rank == 0:
                if len(members) > 1:
                    raise fail(f'the column "{name}" appears {len(members)} times')
                result.append((name, (1,), np.array([members[0][1]])))
                continue
            shape = tuple(max(index[d] for index, _ in members) + 1 for d in range(rank))
            order = np.full(shape, -1, dtype=np.int64)
            for index, column in members:
                if order[index] >= 0:
                    raise fail(f'the column "{header[column]}" appears twice')
                order[index] = column
            if (order < 0).any():
                missing = tuple(int(i) for i in np.argwhere(order < 0)[0])
                raise fail(f'the columns of "{name}" have no element '
                           f'{name}{"".join(f"[{i}]" for i in missing)}')
            result.append((name, shape, order.reshape(-1)))
        return result

    def init(self):
        self._outputs = [(getattr(self, attribute_name(name)).reshape(-1), columns)
                         for name, _, columns in self._groups]
        for out, _ in self._outputs:
            out.fill(0)
        self._step = 0                 # rows output so far, counting repetitions
        self._extend_left = None
        self._eof_sent = False

    def tick(self):
        rows = len(self._data)
        reps = max(1, self.repetitions)
        total = rows * reps * self.iterations if self.iterations > 0 else None
        if rows and (total is None or self._step < total):
            row = self._data[(self._step // reps) % rows]
            for out, columns in self._outputs:
                np.take(row, columns, out=out)
            self._step += 1
            if total is not None and self._step == total:
                self._extend_left = self.extend
                if self.extend <= 0:
                    self._send_end_of_file()
            return
        for out, _ in self._outputs:
            out.fill(0)
        if self._extend_left is None:              # a table without data rows
            self._extend_left = self.extend + 1
        self._extend_left -= 1
        if self._extend_left <= 0:
            self._send_end_of_file()

    def _send_end_of_file(self):
        if self.send_end_of_file and not self._eof_sent:
            self._eof_sent = True
            self.end_of_file(f'end of CSV file "{self.filename}"')


def _is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False
