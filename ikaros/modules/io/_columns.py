"""A base for the modules that write their inputs as a table, one row per tick (OutputCSV,
OutputFile): the ``<column name="X" decimals="2"/>`` child elements, the values of a row and
the file they go to."""
import numpy as np

from ikaros.module import Module, attribute_name


class ColumnWriter(Module):
    """Reads the ``<column>`` child elements into ``self._columns`` ((name, decimals) pairs,
    decimals None where the column does not set it), each becoming an input; lays out the
    inputs' values in one row (``self._slices``, ``self._buffer``); writes a row to
    ``self._file``. The subclass declares ``decimals`` and ``timestamp``."""

    def _read_columns(self, reserved, description, error):
        """Fills ``self._columns`` and adds an input for each column, described as
        ``description`` followed by its name. ``reserved`` are the names of the module's own
        inputs; ``error(element, message)`` makes the exception raised for a bad column."""
        self._columns = []               # (name, decimals)
        elements = list(self.element.elements("column")) if self.element is not None else []
        for column in elements:
            name = column.get("name")
            if not name:
                raise error(column, '<column> needs a name="..." attribute')
            if name in reserved or any(name == c[0] for c in self._columns):
                raise error(column, f'column name "{name}" is used twice')
            decimals = column.get("decimals")
            try:
                decimals = None if decimals in (None, "") else int(decimals)
            except ValueError:
                raise error(column, f'decimals="{decimals}" is not an integer') from None
            if decimals is not None and decimals < 0:
                raise error(column, "decimals must not be negative")
            self._columns.append((name, decimals))
            self.add_input(name, description=f"{description} {name}")

    def _lay_out(self):
        """Sets ``self._slices`` (input, first, end) and ``self._buffer`` for the values of a
        row; returns the columns' inputs and the printf formats of the values, in order."""
        inputs = [getattr(self, attribute_name(name)) for name, _ in self._columns]
        formats, self._slices = [], []
        start = 0
        for (_, decimals), x in zip(self._columns, inputs):
            d = self.decimals if decimals is None else decimals
            formats.extend([f"%.{max(0, d)}f"] * x.size)
            self._slices.append((x, start, start + x.size))
            start += x.size
        self._buffer = np.zeros(start, dtype=np.float64)
        return inputs, formats

    def _write_row(self):
        """Writes this tick's row with ``self._format`` (the tick number first when
        ``timestamp`` is set) to ``self._file``, if it is open, and flushes it."""
        if self._file is None:
            return
        for x, a, b in self._slices:
            self._buffer[a:b] = x.reshape(-1)
        values = self._buffer.tolist()
        if self.timestamp:
            values.insert(0, self.clock.tick)
        self._file.write(self._format % tuple(values))
        self._file.flush()

    def _close(self):
        if getattr(self, "_file", None) is not None:
            self._file.close()
            self._file = None
