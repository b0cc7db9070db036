"""OutputFile: writes its inputs to a file, one record per tick: the Ikaros 2 text table,
CSV, TSV, JSON or JSON Lines."""
import json
import math
import os

import numpy as np

from ikaros.module import Input, ModelError, Parameter, attribute_name

from ._columns import ColumnWriter
from ._csvnames import column_names
from ._files import counter_capacity, model_folder, numbered
_EXTENSIONS = {".csv": "csv", ".tsv": "tsv", ".json": "json", ".jsonl": "jsonl",
               ".ndjson": "jsonl"}
_STAMPS = {"yes": "tick", "true": "tick", "on": "tick", "1": "tick",
           "no": "none", "false": "none", "off": "none", "0": "none",
           "none": "none", "line": "line", "tick": "tick", "time": "time",
           "real_time": "real_time"}


class OutputFile(ColumnWriter):
    """Writes its inputs to a file, one record per tick. The values come from the
    ``<column name="X" decimals="2"/>`` child elements, each of which becomes an input X
    (the Ikaros 2 interface), and from INPUT (the Ikaros 3 interface: connect what is to be
    written to INPUT, naming each connection with its ``label``); columns come first, then
    INPUT. When none of INPUT's connections has a label, INPUT is one value named INPUT (its
    connections laid end to end); otherwise each connection is a value of its own, named by
    its label (one without a label by its source, as ``C.OUTPUT``), with its own shape (a
    delay window adds an outer axis, one entry per delay in the window's order: in an
    Ikaros 2 file the longest delay first). A relative
    ``filename`` is relative to the model file's folder (or to the user-data folder given
    with ``ikaros -u``); a ``%d`` in it (or ``%03d`` and so
    on, Ikaros 2) or a run of ``#`` (Ikaros 3: ``##`` is two digits, zero-padded) is
    replaced by the file number, which starts at ``start_index`` (0).

    ``format`` ``auto`` (the default) writes the Ikaros 2 text table when there are
    ``<column>`` elements (whatever the file is called, as Ikaros 2 did), and otherwise goes
    by the file's extension: ``.csv`` is csv, ``.tsv`` tsv, ``.json`` json, ``.jsonl`` and
    ``.ndjson`` jsonl, anything else the text table (``text``):

    * text: tab-separated, the header ``T/1`` (the stamp) followed by ``X/n`` for each
      value (n elements of X, written flattened), as InputFile reads it;
    * csv, tsv: values separated by ``delimiter`` (csv: "," unless set, tsv: a tab), a
      header row (unless ``header`` is no) naming the stamp column after the stamp kind and
      the elements ``X``, ``X[0]``, ``X[1][2]`` ..., as InputCSV and InputFile read them (a
      name with the delimiter or a quote in it is quoted, quotes doubled);
    * jsonl: one object per line, ``{"tick":3,"weights":[[1,2],[3,4]]}``, each value with
      its shape (a one-element value as a number); json: the same objects in one array,
      kept valid after every record. Values that are not finite are written as null. In
      these formats every connection into INPUT needs a label, the labels must differ (from
      the column names too) and may not be ``tick`` or the stamp's name: else the run stops
      at its start with an error.

    Numbers are written with ``decimals`` decimals (a column may set its own), or with
    ``number_format`` full, as many digits as needed to read the float back exactly.
    ``timestamp`` chooses the stamp of each record: ``tick`` (the tick number), ``line`` (0,
    1, 2 ... per file), ``time`` (the nominal time, tick × tick_duration), ``real_time``
    (seconds since the run started) or ``none``; Ikaros 2's yes and no are tick and none.

    An existing file is replaced (``existing_file`` overwrite), or refused (error: the model
    does not start, or a new file is not begun), or added to (append, or ``append`` yes):
    then the records go after those it has; its header must be the one this module writes
    (else the run stops with an error), and a JSON file must hold an array, which stays one
    valid array. Records are flushed to the disk after every ``flush_interval`` records (0:
    only when the file is closed).

    In a file of dialect 3 the defaults are Ikaros 3's: filename output.csv, format csv,
    timestamp time and existing_file error.

    When WRITE is connected a record is written only on ticks when its first element is
    above 0 (with ``single_trig``, or its Ikaros 3 name ``single_trigger``, only on ticks
    when it rises from 0 or below to above 0).
    When NEWFILE is connected, a rise of its first element from 0 or below to above 0
    closes the file (a JSON array is closed), adds 1 to the file number and opens the next
    file (the same file again, rewritten, when the name has no counter); that tick's record
    goes into the new file. When the next file cannot be opened, or its number does not fit
    in the run of ``#``, a warning says so and the records go on into the current file.
    When ``directory`` is set, the files go into a new folder named after it with a number
    added (``name_0``, ``name_1``, ...: the first that does not exist), created at the start
    of each run."""

    filename = Parameter("output.txt", "the file to write; may contain %d or ## for the file "
                         "number; relative to the model file's folder or the user-data "
                         "folder (ikaros -u)", default_v3="output.csv")
    format = Parameter("auto", "the file format (auto: by the file's extension)",
                       options="auto/text/csv/tsv/json/jsonl", default_v3="csv")
    decimals = Parameter(4, "number of decimals of the columns that do not set their own",
                         type="int")
    number_format = Parameter("fixed", "fixed: decimals decimals; full: every digit needed",
                              options="fixed/full")
    timestamp = Parameter("tick", "the stamp of each record: tick, line, time, real_time "
                          "or none (Ikaros 2: yes is tick, no is none)", default_v3="time")
    delimiter = Parameter("", 'csv and tsv: one character between values ("tab" for a '
                          'tab); empty: "," for csv, a tab for tsv')
    header = Parameter(True, "csv and tsv: write a header row")
    directory = Parameter("", "if set, a new folder with this name and a number added is "
                          "created for the files of each run")
    single_trig = Parameter(False, "write only when WRITE rises from 0 to above 0, not on "
                            "every tick it is above 0")
    single_trigger = Parameter(False, "Ikaros 3 name of single_trig")
    append = Parameter(False, "add to an existing file instead of replacing it (its header "
                       "must be the same; a JSON file must hold an array)")
    existing_file = Parameter("overwrite", "what happens to a file that exists: overwrite "
                              "it, refuse to write it (error), or append to it",
                              options="error/overwrite/append", default_v3="error")
    flush_interval = Parameter(1, "records between flushes to the disk; 0: only when the "
                               "file is closed", type="int", range=(0, None))
    start_index = Parameter(0, "the number of the first file (for %d or ## in filename)",
                            type="int", range=(0, None))
    use_old_format = Parameter(False, "accepted for compatibility and has no effect: the "
                               "text header is always written in the NAME/n form that "
                               "InputFile reads")
    INPUT = Input("Ikaros 3: the values to write, each connection named by its label",
                  optional=True, flatten=True)
    NEWFILE = Input("a rise of the first element to above 0 starts a new file", optional=True)
    WRITE = Input("when connected, a record is written only when the first element is above "
                  "0", optional=True)

    # --- build time -----------------------------------------------------------------------
    def configure(self):
        self._read_columns(("NEWFILE", "WRITE", "INPUT"), "the values of column",
                           self._build_error)
        kind = self.format
        if kind == "auto" and self._columns:        # the Ikaros 2 interface: its format
            kind = "text"
        elif kind == "auto":
            kind = _EXTENSIONS.get(os.path.splitext(self.filename)[1].lower(), "text")
        self._kind = kind
        self._stamp = _STAMPS.get(str(self.timestamp).strip().lower())
        if self._stamp is None:
            raise self._build_error(None, f'timestamp "{self.timestamp}" must be tick, line, '
                                    f'time, real_time or none')
        capacity = counter_capacity(self.filename)
        if capacity is not None and self.start_index >= capacity:
            raise self._build_error(None, f'start_index {self.start_index} does not fit in '
                                    f'"{self.filename}"')
        self._delimiter = "\t"
        if kind in ("csv", "tsv"):
            text = self.delimiter or ("," if kind == "csv" else "tab")
            self._delimiter = "\t" if text.lower() in ("tab", "\\t", "\t") else text
            if len(self._delimiter) != 1 or self._delimiter in "\"'\r\n" or \
                    self._delimiter in "0123456789.-+eE":
                raise self._build_error(None, f'delimiter "{text}" must be one character '
                                        f'that is not a quote, a digit or part of a number')

    def _build_error(self, element, message):
        element = element if element is not None else self.element
        if element is not None and hasattr(element, "error"):
            return element.error(message)
        return ModelError(message)

    # --- run time -------------------------------------------------------------------------
    def init(self):
        self._file = None
        self._path_open = None
        self._number = self.start_index
        self._line = 0                  # records written to the current file in this run
        self._records = 0               # records in the current file (appended ones too)
        self._last_newfile = False
        self._last_write = False
        fields = self._fields()
        if fields is None:
            return
        self._names = [name for name, _, _ in fields]
        self._decimals = [self.decimals if d is None else d for _, d, _ in fields]
        self._values = [values for _, _, values in fields]
        self._shapes = [v().shape for v in self._values]
        self._value_formats = [f"%.{max(0, d)}f" for d, shape in
                               zip(self._decimals, self._shapes) for _ in range(_size(shape))]
        self._full = self.number_format == "full"
        self._appending = self.append or self.existing_file == "append"
        self._folder = self._make_folder()
        if self._folder is not None:
            why = self._open(self._path())
            if why is not None and "already exists" in why:
                raise ValueError(f"OutputFile {why}")
            if why is not None:
                self.fatal_error(f"cannot write output file {why}")

    def _fields(self):
        """(name, decimals, values) of every value written, in order: the ``<column>``
        inputs, then INPUT: one field named INPUT when none of its connections has a label,
        else one per connection, named by its label (or its source). ``values()`` gives the
        value's current array. None after a fatal error (bad labels)."""
        fields = [(name, d, _reader(getattr(self, attribute_name(name))))
                  for name, d in self._columns]
        if self.INPUT is None:
            return fields
        parts = self.input_parts("INPUT")
        if self._kind in ("json", "jsonl"):
            error = self._label_error(parts, {name for name, _ in self._columns})
            if error:
                self.fatal_error(error)
                return None
        if all(p.label is None for p in parts):
            return fields + [("INPUT", None, _reader(self.INPUT))]
        return fields + [(p.name, None, _part_reader(self.INPUT, p)) for p in parts]

    def _label_error(self, parts, taken: set) -> str | None:
        """Why INPUT's connections cannot name JSON fields, or None: each needs a label,
        labels must differ (from the columns too) and may not be the stamp's name."""
        kind = self._kind.upper()
        reserved = {"tick"} | ({self._stamp} if self._stamp != "none" else set())
        for p in parts:
            if p.label is None:
                return (f"{kind} needs a label on every connection into INPUT; the one from "
                        f"{p.source} has none")
            if p.label in reserved:
                return f'{kind}: the label "{p.label}" is reserved for the time stamp'
            if p.label in taken:
                return f'{kind}: the label "{p.label}" is used twice'
            taken.add(p.label)
        return None

    def _header(self):
        stamp = [] if self._stamp == "none" else [self._stamp]
        if self._kind == "text":
            items = ["T/1"] if stamp else []
            items += [f"{name}/{_size(shape)}" for name, shape in zip(self._names, self._shapes)]
            return "\t".join(items) + "\n"
        if self._kind in ("csv", "tsv"):
            if not self.header:
                return ""
            cells = stamp + [c for name, shape in zip(self._names, self._shapes)
                             for c in column_names(name, shape)]
            return self._delimiter.join(_quoted(c, self._delimiter) for c in cells) + "\n"
        return "[\n" if self._kind == "json" else ""

    def _stamp_value(self):
        kind = self._stamp
        if kind == "tick":
            return self.clock.tick
        if kind == "line":
            return self._line
        if kind == "time":
            return self.clock.time
        return self.clock.real_time

    def _record(self):
        arrays = [values() for values in self._values]
        if self._kind in ("json", "jsonl"):
            record = {} if self._stamp == "none" else {self._stamp: self._stamp_value()}
            for name, x, d in zip(self._names, arrays, self._decimals):
                record[name] = _json_value(x, None if self._full else d)
            text = json.dumps(record, allow_nan=False, separators=(",", ":"))
            return (",\n" if self._records else "") + text if self._kind == "json" else \
                text + "\n"
        values = [v for x in arrays for v in x.reshape(-1).tolist()]
        if self._full:
            cells = [_shortest(v) for v in values]
        else:
            cells = [f % v for f, v in zip(self._value_formats, values)]
        if self._stamp != "none":
            stamp = self._stamp_value()
            cells.insert(0, str(stamp) if isinstance(stamp, int) else f"{stamp:g}")
        return self._delimiter.join(cells) + "\n"

    def _base(self):
        """Where relative names go: the user-data folder (-u DIR), else the model's."""
        return self.user_data or model_folder(self)

    def _make_folder(self):
        if not self.directory:
            return self._base()
        stem = self.directory if os.path.isabs(self.directory) else \
            os.path.join(self._base(), self.directory)
        for n in range(100000):
            folder = f"{stem}_{n}"
            if not os.path.exists(folder):
                try:
                    os.makedirs(folder)
                except OSError as e:
                    self.fatal_error(f'cannot create directory "{folder}": {e.strerror}')
                    return None
                return folder
        self.fatal_error(f'no free directory name for "{self.directory}"')
        return None

    def _path(self, number: int | None = None):
        name = numbered(self.filename, self._number if number is None else number)
        return name if os.path.isabs(name) else os.path.join(self._folder, name)

    def _open(self, path: str) -> str | None:
        """Make ``path`` the file written to (closing the current one), with its header or,
        when appending to a file that has records, after them. Returns why it could not,
        or None; then the current file stays open."""
        if path == self._path_open:
            self._close()
        elif self.existing_file == "error" and not self._appending and os.path.exists(path):
            return f'"{path}" already exists (existing_file="error"; overwrite or append to ' \
                   f'write it)'
        try:
            os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
            existing = self._appending and os.path.exists(path) and os.path.getsize(path) > 0
            if existing:
                file, records = self._reopen(path)
            else:
                file, records = open(path, "w", encoding="utf-8"), 0
                file.write(self._header())
        except (OSError, ValueError) as e:
            return f'"{path}": {getattr(e, "strerror", None) or e}'
        self._close()
        self._file, self._path_open = file, path
        self._line, self._records = 0, records
        self._unflushed = 0
        self._end_json()
        self._file.flush()
        return None

    def _reopen(self, path: str):
        """An existing file opened for appending, and the number of records it has (only
        JSON needs it). Its header must be this run's; raises ValueError when not."""
        if self._kind == "json":
            with open(path, encoding="utf-8") as f:
                text = f.read()
            try:
                records = json.loads(text)
            except json.JSONDecodeError:
                records = None
            if not isinstance(records, list):
                raise ValueError("cannot append: it is not a JSON array")
            body = text[:text.rindex("]")].rstrip() + ("" if records else "\n")
            file = open(path, "w", encoding="utf-8")
            file.write(body)
            return file, len(records)
        header = self._header()
        if header:
            with open(path, encoding="utf-8") as f:
                first = f.readline()
            if first != header:
                raise ValueError(f"cannot append: its header {first.strip()!r} differs from "
                                 f"this one, {header.strip()!r}")
        return open(path, "a", encoding="utf-8"), 0

    def _end_json(self):
        """Keeps a JSON file a valid array: the closing bracket is written after every
        record (and at the start) and overwritten by the next."""
        if self._kind == "json":
            self._file.write("\n]\n")
            self._file.seek(self._file.tell() - 3)

    def tick(self):
        if self.NEWFILE is not None:
            rise = bool(self.NEWFILE.flat[0] > 0)
            if rise and not self._last_newfile and self._file is not None:
                self._next_file()
            self._last_newfile = rise
        if self.WRITE is not None:
            on = bool(self.WRITE.flat[0] > 0)
            single = self.single_trig or self.single_trigger
            write = on and not (single and self._last_write)
            self._last_write = on
            if not write:
                return
        if self._file is None:
            return
        self._file.write(self._record())
        self._line += 1
        self._records += 1
        self._end_json()
        self._unflushed += 1
        if self.flush_interval and self._unflushed >= self.flush_interval:
            self._file.flush()
            self._unflushed = 0

    def _next_file(self):
        """NEWFILE rose: go on in the file with the next number; when that cannot be, warn
        and go on in the current file."""
        number = self._number + 1
        capacity = counter_capacity(self.filename)
        if capacity is not None and number >= capacity:
            why = f'file number {number} does not fit in "{self.filename}"'
        else:
            why = self._open(self._path(number))
        if why is None:
            self._number = number
        elif self._file is None:        # the same file again, and it could not be rewritten
            self.fatal_error(f"cannot write output file {why}")
        else:
            self.warning(f"cannot start a new file: {why}; continuing with "
                         f'"{self._path_open}"')

    def stop(self):
        self._close()

    def _close(self):
        super()._close()
        self._path_open = None


def _size(shape: tuple) -> int:
    return int(np.prod(shape)) if shape else 1


def _reader(array: np.ndarray):
    return lambda: array


def _part_reader(array: np.ndarray, part):
    return lambda: part.values(array)


def _quoted(cell: str, delimiter: str) -> str:
    """A header cell, quoted (with quotes doubled) when it holds the delimiter or a quote."""
    if delimiter in cell or '"' in cell or "\n" in cell:
        return '"' + cell.replace('"', '""') + '"'
    return cell


def _shortest(v: float) -> str:
    """The shortest text that reads back as the same float32."""
    return str(np.float32(v))


def _json_value(x: np.ndarray, decimals: int | None):
    """A value for JSON: a number for one element, else nested lists; non-finite as None.
    Numbers are rounded to ``decimals`` (None: the shortest exact float32 text)."""
    def number(v):
        v = float(v)
        if not math.isfinite(v):
            return None
        v = float(_shortest(v)) if decimals is None else round(v, decimals)
        return int(v) if v.is_integer() and abs(v) < 2 ** 53 else v
    if x.size == 1 and x.ndim <= 1:
        return number(x.reshape(-1)[0])
    return np.vectorize(number, otypes=[object])(x).tolist()
