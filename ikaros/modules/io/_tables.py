"""Tables read whole when a model loads (CSV and JSON), and playing their rows one per tick:
shared by InputCSV and InputFile.

A table is ``(groups, data)``: ``data`` is a float32 matrix of one row per tick, and each
group ``(name, shape, columns)`` is an output of that shape whose elements, in row-major
order, are the given columns of a row.
"""
import csv
import json

import numpy as np

from ._csvnames import parse_column, port_name
from ._files import build_error


def read_csv(module, path: str, shown: str, delimiter: str, header: bool = True,
             multi_value: bool = False):
    """A CSV table. With ``header`` the first row names the columns (grouped by name, see
    InputCSV); without it every column belongs to one output, OUTPUT. Empty cells are 0 and
    short rows are padded with 0. With ``multi_value`` a cell may hold several values
    separated by spaces: each column is then an output of as many elements as its cell in
    the first data row."""
    try:
        with open(path, encoding="utf-8-sig", newline="") as f:
            rows = list(enumerate(csv.reader(f, delimiter=delimiter), 1))
    except OSError as e:
        raise build_error(module, f'cannot read "{shown}": {e.strerror}') from None
    except (UnicodeDecodeError, csv.Error) as e:
        raise build_error(module, f'cannot read "{shown}": {e}') from None
    if delimiter == " ":                    # runs of spaces are one delimiter
        rows = [(n, [c for c in r if c]) for n, r in rows]
    rows = [(n, r) for n, r in rows if any(cell.strip() for cell in r)]
    if not rows:
        raise build_error(module, f'"{shown}" is empty')
    header_line, names = rows[0] if header else (0, None)
    if header:
        rows = rows[1:]
    columns = len(names) if names is not None else max(len(r) for _, r in rows)
    widths = [1] * columns
    if multi_value and rows:
        first = rows[0][1]
        widths = [max(1, len(first[c].split())) if c < len(first) else 1
                  for c in range(columns)]
    starts = np.cumsum([0] + widths)
    data = np.zeros((len(rows), int(starts[-1])), dtype=np.float32)
    for r, (line, cells) in enumerate(rows):
        if len(cells) > columns:
            raise build_error(module, f"{path}:{line}: {len(cells)} values but the "
                              f"{'header' if names else 'table'} has {columns} columns")
        for c, cell in enumerate(cells):
            label = f'"{names[c]}"' if names else str(c + 1)
            values = cell.split() if multi_value else [cell.strip()] if cell.strip() else []
            if values and len(values) != widths[c]:
                raise build_error(module, f"{path}:{line}: column {label} holds "
                                  f"{len(values)} values, {widths[c]} in the first row")
            try:
                data[r, starts[c]:starts[c] + len(values)] = [float(v) for v in values]
            except ValueError:
                raise build_error(module, f'{path}:{line}: "{cell.strip()}" in column '
                                  f'{label} is not a number') from None
    if names is None:
        return [("OUTPUT", (int(starts[-1]),), np.arange(int(starts[-1])))], data
    if any(w != 1 for w in widths):
        groups = [(port_name(n), (w,), np.arange(a, a + w))
                  for n, w, a in zip(names, widths, starts)]
        return _unique(module, path, header_line, groups), data
    return group_columns(module, path, header_line, names), data


def _unique(module, path, line, groups):
    seen = set()
    for name, _, _ in groups:
        if name in seen:
            raise build_error(module, f'{path}:{line}: the column "{name}" appears twice')
        seen.add(name)
    return groups


def group_columns(module, path: str, line: int, header: list[str]):
    """Groups header cells into outputs: X, X[i], X[i][j] ... (see InputCSV)."""
    def fail(message):
        return build_error(module, f"{path}:{line}: {message}")
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


def _is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def read_json(module, path: str, shown: str, lines: bool):
    """A table from JSON: an array of objects (``lines`` false) or one object per line
    (JSON Lines). Each key is an output (its name made a valid port name); its value is a
    number, true/false, null (NaN) or a nested list of them, of the same shape in every
    record."""
    try:
        with open(path, encoding="utf-8-sig") as f:
            text = f.read()
    except OSError as e:
        raise build_error(module, f'cannot read "{shown}": {e.strerror}') from None
    except UnicodeDecodeError as e:
        raise build_error(module, f'cannot read "{shown}": {e}') from None
    records = []            # (where, object)
    try:
        if lines:
            for number, line in enumerate(text.splitlines(), 1):
                if line.strip():
                    records.append((f"{path}:{number}", json.loads(line)))
        else:
            loaded = json.loads(text)
            if not isinstance(loaded, list):
                raise build_error(module, f"{path}: a JSON file must hold an array of "
                                  f"objects, one per tick")
            records = [(f"{path}: record {k + 1}", r) for k, r in enumerate(loaded)]
    except json.JSONDecodeError as e:
        where = f"{path}:{number}" if lines else f"{path}:{e.lineno}"
        raise build_error(module, f"{where}: not valid JSON: {e.msg}") from None
    if not records:
        raise build_error(module, f'"{shown}" has no records')
    layout = None           # [(key, name, shape)]
    rows = []
    for where, record in records:
        if not isinstance(record, dict):
            raise build_error(module, f"{where}: a record must be a JSON object")
        if layout is None:
            layout = [(key, port_name(key), _shape(module, where, key, value))
                      for key, value in record.items()]
            _unique(module, path, 1, [(n, None, None) for _, n, _ in layout])
        elif list(record) != [key for key, _, _ in layout]:
            raise build_error(module, f"{where}: the keys {list(record)} differ from the "
                              f"first record's {[k for k, _, _ in layout]}")
        row = []
        for key, _, shape in layout:
            value = record[key]
            if _shape(module, where, key, value) != shape:
                raise build_error(module, f'{where}: "{key}" has shape '
                                  f'{_shape(module, where, key, value)}, but {shape} in the '
                                  f'first record')
            row.extend(np.asarray(_numbers(value), dtype=np.float64).reshape(-1).tolist())
        rows.append(row)
    groups, at = [], 0
    for _, name, shape in layout:
        size = int(np.prod(shape))
        groups.append((name, shape, np.arange(at, at + size)))
        at += size
    return groups, np.array(rows, dtype=np.float32).reshape(len(rows), at)


def _numbers(value):
    if isinstance(value, list):
        return [_numbers(v) for v in value]
    return float("nan") if value is None else float(value)


def _shape(module, where, key, value) -> tuple:
    """The shape of a JSON value: (1,) for a number, the nested list's shape otherwise."""
    if isinstance(value, bool) or value is None or isinstance(value, (int, float)):
        return (1,)
    if isinstance(value, list):
        try:
            array = np.asarray(_numbers(value), dtype=np.float64)
        except (TypeError, ValueError):
            array = None
        if array is not None and array.dtype != object and array.size:
            return array.shape
    raise build_error(module, f'{where}: "{key}" is not a number or a regular, non-empty '
                      f'array of numbers')


class RowPlayer:
    """Outputs the rows of a table one per tick: row k on tick k (the outputs are 0 in
    init), each row ``repetitions`` times, the table ``iterations`` times (0: forever); then
    zeros, and ``extend`` ticks later end-of-file unless ``send_end_of_file`` is no. The
    module declares those parameters; ``outputs`` are (flat output array, columns) pairs."""

    def __init__(self, module, data, outputs, what: str, on_iteration=None):
        self.module, self.data, self.outputs, self.what = module, data, outputs, what
        self.on_iteration = on_iteration
        self.step = 0                 # rows output so far, counting repetitions
        self.extend_left = None
        self.eof_sent = False
        for out, _ in outputs:
            out.fill(0)

    def tick(self):
        m, rows = self.module, len(self.data)
        reps = max(1, m.repetitions)
        total = rows * reps * m.iterations if m.iterations > 0 else None
        if rows and (total is None or self.step < total):
            if self.on_iteration and self.step % (rows * reps) == 0:
                self.on_iteration(self.step // (rows * reps) + 1)
            row = self.data[(self.step // reps) % rows]
            for out, columns in self.outputs:
                np.take(row, columns, out=out)
            self.step += 1
            if total is not None and self.step == total:
                self.extend_left = m.extend
                if m.extend <= 0:
                    self._send_end_of_file()
            return
        for out, _ in self.outputs:
            out.fill(0)
        if self.extend_left is None:              # a table without data rows
            self.extend_left = m.extend + 1
        self.extend_left -= 1
        if self.extend_left <= 0:
            self._send_end_of_file()

    def _send_end_of_file(self):
        if self.module.send_end_of_file and not self.eof_sent:
            self.eof_sent = True
            self.module.end_of_file(f"end of {self.what}")
