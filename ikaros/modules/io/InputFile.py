"""InputFile: reads a table of values, one row per tick: the Ikaros 2 text format, CSV,
JSON or JSON Lines."""
import os
import re

import numpy as np

from ikaros.module import ModelError, Module, Parameter, attribute_name

from ._csvnames import csv_delimiter
from ._tables import RowPlayer, read_csv, read_json

_EXTENSIONS = {".csv": "csv", ".tsv": "tsv", ".json": "json", ".jsonl": "jsonl",
               ".ndjson": "jsonl"}

_HEADER_ITEM = re.compile(r"^([A-Za-z_][\w\-]*)(?:/(\d+))?$")


class InputFile(Module):
    """Reads a whitespace-separated text file in the Ikaros 2 format. The first line that is
    not blank or a comment is a header such as ``X/2 Y/1``: each ``NAME/n`` becomes an output
    NAME of n elements (``NAME`` alone means ``NAME/1``). Every following line holds the values
    of one tick for all outputs, in header order. ``#`` starts a comment and blank lines are
    skipped. A relative ``filename`` is relative to the model file's folder.

    In ``dynamic`` mode line k of the data is output on tick k (the outputs are 0 in init);
    each line is repeated ``repetitions`` times and the whole file is read ``iterations``
    times (0 means forever). After the last line the outputs are 0; ``extend`` ticks later
    the module sends end-of-file, which stops the run, unless ``send_end_of_file`` is no. In
    ``static`` mode the whole file is output at once and never changes: an output NAME/n is
    a matrix of one row per data line and n columns.

    ``format`` chooses the file format; ``auto`` (the default) goes by the file's extension:
    ``.csv`` is csv, ``.tsv`` tsv, ``.json`` json, ``.jsonl`` and ``.ndjson`` jsonl, anything
    else the Ikaros 2 text format above (``ikaros``, or Ikaros 3's name ``text``); a .csv or .tsv file whose header is in
    the Ikaros 2 form (``X/2 Y/1``) is read in that format, as Ikaros 2 did. The other
    formats are those of Ikaros 3, read whole when the model loads. csv and tsv: values separated by
    ``delimiter`` (csv: "," unless set; tsv: a tab; a space means runs of spaces); with
    ``header`` (the default) the first row names the columns: ``X`` is an output of one
    element, ``X[0]``, ``X[1]`` ... form a vector and ``X[i][j]`` a matrix (as InputCSV), or,
    when a cell of the first data row holds several values separated by spaces, each column
    is an output of that many elements; without a header all columns form one output,
    OUTPUT. Empty cells are 0. json: an array of objects, one per tick; jsonl: one object per
    line. Each key is an output whose shape is that of its value (a number is one element; a
    nested list a vector, matrix, ...), the same in every record; true, false and null are
    1, 0 and NaN. A name that is not a valid port name has its other characters replaced by
    ``_``. In static mode an output gets a leading axis of one row per record."""

    filename = Parameter("", "the file to read; relative to the model file's folder")
    type = Parameter("dynamic", "dynamic: one line per tick; static: the whole file as a "
                     "matrix that does not change", options="dynamic/static")
    iterations = Parameter(1, "how many times the file is read; 0 means forever", type="int")
    repetitions = Parameter(1, "how many ticks each line is output", type="int")
    extend = Parameter(0, "ticks to run after the last line before end-of-file is sent, so "
                       "the data can propagate through the network", type="int")
    send_end_of_file = Parameter(True, "send end-of-file (stopping the run) when the data "
                                 "is exhausted; with no, the outputs are 0 forever")
    print_iteration = Parameter(False, "print the number of each iteration as it starts")
    format = Parameter("auto", "the file format (auto: by the file's extension)",
                       options="auto/text/csv/tsv/json/jsonl/ikaros")
    delimiter = Parameter("", 'csv and tsv: the character between values ("tab" for a tab); '
                          'empty: "," for csv, a tab for tsv')
    header = Parameter(True, "csv and tsv: the first row names the columns")

    # --- build time -----------------------------------------------------------------------
    def configure(self):
        self._file_path = self._resolve(self.filename)
        kind = "ikaros" if self.format == "text" else self.format
        if kind == "auto":
            kind = _EXTENSIONS.get(os.path.splitext(self.filename)[1].lower(), "ikaros")
            if kind in ("csv", "tsv") and self._ikaros_header():
                kind = "ikaros"
        self._table = None
        if kind != "ikaros":
            self._configure_table(kind)
            return
        try:
            with open(self._file_path, encoding="utf-8") as f:
                header, header_line = None, 0
                for number, line in enumerate(f, 1):
                    tokens = line.split("#", 1)[0].split()
                    if tokens:
                        header, header_line = tokens, number
                        break
                rest = f.readlines() if self.type == "static" else []
        except OSError as e:
            raise self._build_error(f'cannot read input file "{self.filename}": '
                                    f'{e.strerror}') from None
        except UnicodeDecodeError:
            raise self._build_error(f'input file "{self.filename}" is not UTF-8 text') from None
        if header is None:
            raise self._build_error(f'input file "{self.filename}" has no header line')
        self._columns = []            # (name, first, end) of each output in a data row
        width = 0
        for item in header:
            match = _HEADER_ITEM.match(item)
            if not match or (match.group(2) is not None and int(match.group(2)) < 1):
                raise self._build_error(f'{self._file_path}:{header_line}: bad header item '
                                        f'"{item}" (expected NAME/n)')
            name, n = match.group(1), int(match.group(2) or 1)
            if any(name == c[0] for c in self._columns):
                raise self._build_error(f'{self._file_path}:{header_line}: the header names '
                                        f'"{name}" twice')
            self._columns.append((name, width, width + n))
            width += n
        self._width = width
        self._header_line = header_line

        if self.type == "static":
            rows = []
            for number, line in enumerate(rest, header_line + 1):
                row = self._parse(line, number)
                if isinstance(row, str):
                    raise self._build_error(row)
                if row is not None:
                    rows.append(row)
            if not rows:
                raise self._build_error(f'input file "{self.filename}" has no data lines')
            self._data = np.array(rows, dtype=np.float32)
            for name, a, b in self._columns:
                self.add_output(name, (len(rows), b - a),
                                description=f"column group {name}: one row per data line")
        else:
            for name, a, b in self._columns:
                self.add_output(name, (b - a,),
                                description=f"column group {name} of the current line")

    def _ikaros_header(self) -> bool:
        """Whether the file starts with an Ikaros 2 header (``X/2 Y/1``, white space between
        the items and no comma or tab), as Ikaros 2 files named .csv do."""
        try:
            with open(self._file_path, encoding="utf-8-sig") as f:
                for line in f:
                    text = line.split("#", 1)[0].strip()
                    if text:
                        items = text.split()
                        return "," not in text and "\t" not in text and \
                            any("/" in i for i in items) and \
                            all(_HEADER_ITEM.match(i) for i in items)
        except (OSError, UnicodeDecodeError):
            pass            # reported when the file is read
        return False

    def _configure_table(self, kind):
        """Reads a CSV, TSV, JSON or JSONL file whole and declares its outputs."""
        shown = f"input file {self.filename}"
        if kind in ("json", "jsonl"):
            groups, data = read_json(self, self._file_path, shown, lines=kind == "jsonl")
        else:
            if not self.delimiter:
                self.delimiter = "," if kind == "csv" else "tab"
            groups, data = read_csv(self, self._file_path, shown, csv_delimiter(self),
                                    header=self.header, multi_value=True)
        self._table = (groups, data)
        static = self.type == "static"
        for name, shape, _ in groups:
            self.add_output(name, (len(data),) + shape if static else shape,
                            description=f"{name} of the current row" if not static else
                            f"{name} of every row")

    def _resolve(self, filename):
        if not filename:
            raise self._build_error("InputFile needs a filename")
        if os.path.isabs(filename):
            return filename
        model_file = getattr(self.element, "file", None)
        base = os.path.dirname(model_file) if model_file else os.getcwd()
        return os.path.join(base, filename)

    def _build_error(self, message):
        if self.element is not None and hasattr(self.element, "error"):
            return self.element.error(message)
        return ModelError(message)

    def _parse(self, line, number):
        """A data row, None for a blank or comment line, or an error message."""
        tokens = line.split("#", 1)[0].split()
        if not tokens:
            return None
        if len(tokens) != self._width:
            return (f"{self._file_path}:{number}: expected {self._width} values, found "
                    f"{len(tokens)}")
        try:
            return np.array(tokens, dtype=np.float32)
        except ValueError:
            return f"{self._file_path}:{number}: not a number in \"{line.strip()}\""

    # --- run time -------------------------------------------------------------------------
    def init(self):
        self._file = None
        if self._table is not None:
            groups, data = self._table
            if self.type == "static":
                for name, _, columns in groups:
                    out = getattr(self, attribute_name(name))
                    out[...] = data[:, columns].reshape(out.shape)
                self._player = None
            else:
                outputs = [(getattr(self, attribute_name(name)).reshape(-1), columns)
                           for name, _, columns in groups]
                self._player = RowPlayer(
                    self, data, outputs, f'input file "{self.filename}"',
                    self._show_iteration if self.print_iteration else None)
            return
        self._outputs = [(getattr(self, attribute_name(name)), a, b)
                         for name, a, b in self._columns]
        if self.type == "static":
            self._write(self._data)
            return
        for out, _, _ in self._outputs:
            out.fill(0)
        self._iteration = 0          # iteration of the lookahead row
        self._reps_left = 0
        self._done = False
        self._failed = False
        self._eof_sent = False
        self._extend_left = 0
        self._shown_iteration = -1
        try:
            self._file = open(self._file_path, encoding="utf-8")
        except OSError as e:
            self.fatal_error(f'cannot read input file "{self.filename}": {e.strerror}')
            self._failed = True
            return
        for _ in range(self._header_line):
            self._file.readline()
        self._line_number = self._header_line
        self._data_start = self._file.tell()
        self._next = self._fetch()
        self._current = None
        if self._next is None:
            self.warning(f'input file "{self.filename}" has no data lines')

    def _fetch(self):
        """The next data row of the file, across iterations; None when the data are
        exhausted; an error message for a bad line."""
        restarted = False
        while True:
            line = self._file.readline()
            if line == "":
                last = self.iterations > 0 and self._iteration + 1 >= self.iterations
                if last or restarted:      # restarted: a pass without any data lines
                    return None
                self._file.seek(self._data_start)
                self._line_number = self._header_line
                self._iteration += 1
                restarted = True
                continue
            self._line_number += 1
            row = self._parse(line, self._line_number)
            if row is not None:
                return row         # a row, or an error message reported when it is due

    def _write(self, row):
        for out, a, b in self._outputs:
            out[...] = row[..., a:b]

    def _send_end_of_file(self):
        if self.send_end_of_file and not self._eof_sent:
            self._eof_sent = True
            self.end_of_file(f'end of input file "{self.filename}"')

    def _show_iteration(self, number):
        self.print(f"iteration {number}")

    def tick(self):
        if self._table is not None:
            if self._player is not None:
                self._player.tick()
            return
        if self.type == "static":
            self._write(self._data)
            return
        if self._failed:
            return
        if not self._done:
            if self._reps_left <= 0:
                if self._next is None:       # a file without data lines
                    self._done = True
                    self._extend_left = self.extend + 1
                else:
                    if self.print_iteration and self._iteration != self._shown_iteration:
                        self._shown_iteration = self._iteration
                        self.print(f"iteration {self._iteration + 1}")
                    if isinstance(self._next, str):
                        self.fatal_error(self._next)
                        self._failed = True
                        return
                    self._current = self._next
                    self._reps_left = max(1, self.repetitions)
                    self._next = self._fetch()
            if not self._done:
                self._write(self._current)
                self._reps_left -= 1
                if self._reps_left <= 0 and self._next is None:
                    self._done = True
                    self._extend_left = self.extend
                    if self._extend_left <= 0:
                        self._send_end_of_file()
                return
        for out, _, _ in self._outputs:
            out.fill(0)
        if self._extend_left > 0:
            self._extend_left -= 1
        if self._extend_left <= 0:
            self._send_end_of_file()

    def stop(self):
        if getattr(self, "_file", None) is not None:
            self._file.close()
            self._file = None
