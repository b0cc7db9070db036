"""OutputCSV: writes its inputs to a CSV table with a header row, one row per tick."""
import csv

import numpy as np

from ikaros.module import Input, Module, Parameter, attribute_name

from ._csvnames import column_names
from ._files import build_error, resolve


class OutputCSV(Module):
    """Writes a CSV file that spreadsheets and InputCSV read. The columns are declared by
    ``<column name="X" decimals="2"/>`` child elements; each becomes an input X. The first
    row is a header: ``T`` (the tick number, left out when ``timestamp`` is no), then for
    each input its column names: ``X`` when it has a single element, ``X[0]``, ``X[1]``, ...
    for a vector, and ``X[0][0]``, ``X[0][1]``, ... (row-major) for a matrix or higher rank.
    Every tick then writes one row of values with the column's number of decimals
    (``decimals`` unless the column says otherwise), using a point as the decimal mark.
    When WRITE is connected a row is written only on ticks when its first element is above
    0. A relative ``filename`` is relative to the model file's folder; the file is
    rewritten at the start of each run and flushed after every row."""

    filename = Parameter("output.csv", "the CSV file to write; relative to the model file's "
                         "folder")
    decimals = Parameter(4, "number of decimals of the columns that do not set their own",
                         type="int")
    timestamp = Parameter(True, "write the tick number as the first column, T")
    delimiter = Parameter(",", 'the character between values: "," (the default), ";", or '
                          '"tab"')
    WRITE = Input("when connected, a row is written only when the first element is above 0",
                  optional=True)

    def configure(self):
        self._columns = []               # (name, decimals)
        elements = list(self.element.elements("column")) if self.element is not None else []
        for column in elements:
            name = column.get("name")
            if not name:
                raise self._error(column, '<column> needs a name="..." attribute')
            if name == "WRITE" or any(name == c[0] for c in self._columns):
                raise self._error(column, f'column name "{name}" is used twice')
            decimals = column.get("decimals")
            try:
                decimals = None if decimals in (None, "") else int(decimals)
            except ValueError:
                raise self._error(column, f'decimals="{decimals}" is not an integer') \
                    from None
            if decimals is not None and decimals < 0:
                raise self._error(column, "decimals must not be negative")
            self._columns.append((name, decimals))
            self.add_input(name, description=f"the values of column group {name}")
        if not self._columns:
            raise build_error(self, 'OutputCSV needs at least one <column name="..."/>')
        self._delimiter = "\t" if self.delimiter.lower() in ("tab", "\\t", "\t") \
            else self.delimiter
        if len(self._delimiter) != 1:
            raise build_error(self, f'delimiter "{self.delimiter}" must be one character')

    def _error(self, element, message):
        return element.error(message) if hasattr(element, "error") else build_error(self,
                                                                                   message)

    def init(self):
        self._file = None
        header, formats, self._slices = [], [], []
        if self.timestamp:
            header.append("T")
            formats.append("%d")
        start = 0
        for name, decimals in self._columns:
            x = getattr(self, attribute_name(name))
            d = self.decimals if decimals is None else decimals
            header.extend(column_names(name, x.shape))
            formats.extend([f"%.{max(0, d)}f"] * x.size)
            self._slices.append((x, start, start + x.size))
            start += x.size
        self._buffer = np.zeros(start, dtype=np.float64)
        self._format = self._delimiter.join(formats) + "\r\n"
        path = resolve(self, self.filename)
        try:
            self._file = open(path, "w", encoding="utf-8", newline="")
        except OSError as e:
            raise OSError(e.errno, f'cannot write CSV file "{path}": {e.strerror}') from None
        self._writer = csv.writer(self._file, delimiter=self._delimiter)
        self._writer.writerow(header)
        self._file.flush()

    def tick(self):
        if self.WRITE is not None and not self.WRITE.flat[0] > 0:
            return
        if self._file is None:
            return
        for x, a, b in self._slices:
            self._buffer[a:b] = x.reshape(-1)
        values = self._buffer.tolist()
        if self.timestamp:
            values.insert(0, self.clock.tick)
        self._file.write(self._format % tuple(values))
        self._file.flush()

    def stop(self):
        if getattr(self, "_file", None) is not None:
            self._file.close()
            self._file = None
