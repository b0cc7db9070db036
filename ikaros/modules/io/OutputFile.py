"""OutputFile: writes its inputs to a file, one record per tick: the Ikaros 2 text table,
CSV, TSV, JSON or JSON Lines."""
import json
import math
import os

import numpy as np

from ikaros.errors import ModelError
from ikaros.module import Input, Parameter

from ._columns import ColumnWriter
from ._csvnames import column_names
from ._files import numbered
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
    written to INPUT); columns come first, then INPUT. A relative ``filename`` is relative to
    the model file's folder; a ``%d`` in it (or ``%03d`` and so on, Ikaros 2) or a run of
    ``#`` (Ikaros 3: ``##`` is two digits, zero-padded) is replaced by the file number,
    which starts at 0.

    ``format`` ``auto`` (the default) writes the Ikaros 2 text table when there are
    ``<column>`` elements (whatever the file is called, as Ikaros 2 did), and otherwise goes
    by the file's extension: ``.csv`` is csv, ``.tsv`` tsv, ``.json`` json, ``.jsonl`` and
    ``.ndjson`` jsonl, anything else the text table (``text``):

    * text: tab-separated, the header ``T/1`` (the stamp) followed by ``X/n`` for each
      column (n elements of X, written flattened), as InputFile reads it;
    * csv, tsv: values separated by ``delimiter`` (csv: "," unless set, tsv: a tab), a
      header row (unless ``header`` is no) naming the stamp column after the stamp kind and
      the elements ``X``, ``X[0]``, ``X[1][2]`` ..., as InputCSV and InputFile read them;
    * jsonl: one object per line, ``{"tick": 3, "X": [[1, 2], [3, 4]]}``, each value with
      its shape (a one-element value as a number); json: the same objects in one array,
      kept valid after every record. Values that are not finite are written as null.

    Numbers are written with ``decimals`` decimals (a column may set its own), or with
    ``number_format`` full, as many digits as needed to read the float back exactly.
    ``timestamp`` chooses the stamp of each record: ``tick`` (the tick number), ``line`` (0,
    1, 2 ... per file), ``time`` (the nominal time, tick × tick_duration), ``real_time``
    (seconds since the run started) or ``none``; Ikaros 2's yes and no are tick and none.

    When WRITE is connected a record is written only on ticks when its first element is
    above 0 (with ``single_trig``, or its Ikaros 3 name ``single_trigger``, only on ticks
    when it rises from 0 or below to above 0).
    When NEWFILE is connected, a rise of its first element from 0 or below to above 0
    closes the file, adds 1 to the file number and opens the next file (the same file again,
    rewritten, when the name has no %d); that tick's record goes into the new file. When
    ``directory`` is set, the files go into a new folder named after it with a number added
    (``name_0``, ``name_1``, ...: the first that does not exist), created at the start of
    each run."""

    filename = Parameter("output.txt", "the file to write; may contain %d or ## for the file "
                         "number; relative to the model file's folder")
    format = Parameter("auto", "the file format (auto: by the file's extension)",
                       options="auto/text/csv/tsv/json/jsonl")
    decimals = Parameter(4, "number of decimals of the columns that do not set their own",
                         type="int")
    number_format = Parameter("fixed", "fixed: decimals decimals; full: every digit needed",
                              options="fixed/full")
    timestamp = Parameter("tick", "the stamp of each record: tick, line, time, real_time "
                          "or none (Ikaros 2: yes is tick, no is none)")
    delimiter = Parameter("", 'csv and tsv: one character between values ("tab" for a '
                          'tab); empty: "," for csv, a tab for tsv')
    header = Parameter(True, "csv and tsv: write a header row")
    directory = Parameter("", "if set, a new folder with this name and a number added is "
                          "created for the files of each run")
    single_trig = Parameter(False, "write only when WRITE rises from 0 to above 0, not on "
                            "every tick it is above 0")
    single_trigger = Parameter(False, "Ikaros 3 name of single_trig")
    use_old_format = Parameter(False, "accepted for compatibility and has no effect: the "
                               "text header is always written in the NAME/n form that "
                               "InputFile reads")
    INPUT = Input("Ikaros 3: the values to write (one connection keeps its shape; several "
                  "are laid end to end)",
                  optional=True)
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
        self._number = 0
        self._line = 0
        self._last_newfile = False
        self._last_write = False
        if self.INPUT is not None:
            self._columns.append(("INPUT", None))
        self._inputs, self._value_formats = self._lay_out()
        self._full = self.number_format == "full"
        self._names = [name for name, _ in self._columns]
        self._decimals = [self.decimals if d is None else d for _, d in self._columns]
        self._folder = self._make_folder()
        if self._folder is not None:
            self._open()

    def _header(self):
        stamp = [] if self._stamp == "none" else [self._stamp]
        if self._kind == "text":
            items = ["T/1"] if stamp else []
            items += [f"{name}/{x.size}" for name, x in zip(self._names, self._inputs)]
            return "\t".join(items) + "\n"
        if self._kind in ("csv", "tsv"):
            if not self.header:
                return ""
            cells = stamp + [c for name, x in zip(self._names, self._inputs)
                             for c in column_names(name, x.shape)]
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
        for x, a, b in self._slices:
            self._buffer[a:b] = x.reshape(-1)
        values = self._buffer.tolist()
        if self._kind in ("json", "jsonl"):
            record = {} if self._stamp == "none" else {self._stamp: self._stamp_value()}
            for name, x, d in zip(self._names, self._inputs, self._decimals):
                record[name] = _json_value(x, None if self._full else d)
            text = json.dumps(record, allow_nan=False)
            return (",\n" if self._line else "") + text if self._kind == "json" else \
                text + "\n"
        if self._full:
            cells = [_shortest(v) for v in values]
        else:
            cells = [f % v for f, v in zip(self._value_formats, values)]
        if self._stamp != "none":
            stamp = self._stamp_value()
            cells.insert(0, str(stamp) if isinstance(stamp, int) else f"{stamp:g}")
        return self._delimiter.join(cells) + "\n"

    def _base(self):
        model_file = getattr(self.element, "file", None)
        return os.path.dirname(model_file) if model_file else os.getcwd()

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

    def _path(self):
        name = numbered(self.filename, self._number)
        return name if os.path.isabs(name) else os.path.join(self._folder, name)

    def _open(self):
        self._close()
        path = self._path()
        self._line = 0
        try:
            os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
            self._file = open(path, "w", encoding="utf-8")
            self._file.write(self._header())
            self._end_json()
        except OSError as e:
            self._file = None
            self.fatal_error(f'cannot write output file "{path}": {e.strerror}')

    def _end_json(self):
        """Keeps a JSON file a valid array: the closing bracket is written after every
        record (and at the start) and overwritten by the next."""
        if self._kind == "json":
            self._file.write("\n]\n")
            self._file.seek(self._file.tell() - 3)
        self._file.flush()

    def tick(self):
        if self.NEWFILE is not None:
            rise = bool(self.NEWFILE.flat[0] > 0)
            if rise and not self._last_newfile and self._folder is not None:
                self._number += 1
                self._open()
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
        self._end_json()

    def stop(self):
        self._close()


def _quoted(cell: str, delimiter: str) -> str:
    return f'"{cell}"' if delimiter in cell or '"' in cell else cell


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
