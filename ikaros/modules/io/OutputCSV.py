"""OutputCSV: writes its inputs to a CSV table with a header row, one row per tick."""
import csv

from ikaros.module import Input, Parameter

from ._columns import ColumnWriter
from ._csvnames import column_names, csv_delimiter
from ._files import build_error, resolve


class OutputCSV(ColumnWriter):
    """Writes a CSV file that spreadsheets and InputCSV read. The columns are declared by
    ``<column name="X" decimals="2"/>`` child elements; each becomes an input X. The first
    row is a header: ``T`` (the tick number, left out when ``timestamp`` is no), then for
    each input its column names: ``X`` when it has a single element, ``X[0]``, ``X[1]``, ...
    for a vector, and ``X[0][0]``, ``X[0][1]``, ... (row-major) for a matrix or higher rank.
    Every tick then writes one row of values with the column's number of decimals
    (``decimals`` unless the column says otherwise), using a point as the decimal mark.
    When WRITE is connected a row is written only on ticks when its first element is above
    0. A relative ``filename`` is relative to the model file's folder (or to the user-data
    folder given with ``ikaros -u``); the file is rewritten at the start of each run and flushed after every row."""

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
        self._read_columns(("WRITE",), "the values of column group", self._error)
        if not self._columns:
            raise build_error(self, 'OutputCSV needs at least one <column name="..."/>')
        self._delimiter = csv_delimiter(self)

    def _error(self, element, message):
        return element.error(message) if hasattr(element, "error") else build_error(self,
                                                                                   message)

    def init(self):
        self._file = None
        header, formats = [], []
        if self.timestamp:
            header.append("T")
            formats.append("%d")
        inputs, value_formats = self._lay_out()
        for (name, _), x in zip(self._columns, inputs):
            header.extend(column_names(name, x.shape))
        formats.extend(value_formats)
        self._format = self._delimiter.join(formats) + "\r\n"
        path = resolve(self, self.filename, write=True)
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
        self._write_row()

    def stop(self):
        self._close()
