"""OutputFile: writes its inputs to a text table, one line per tick."""
import os
import re

from ikaros.errors import ModelError
from ikaros.module import Input, Parameter

from ._columns import ColumnWriter

_COUNTER = re.compile(r"%(0?\d*)d")


class OutputFile(ColumnWriter):
    """Writes a tab-separated text file in the Ikaros 2 format that InputFile reads. The
    columns are declared by ``<column name="X" decimals="2"/>`` child elements; each column
    becomes an input X, written flattened as one group of values. The header line is
    ``T/1`` followed by ``X/n`` for each column (n is the number of elements of X); then
    every tick writes one line: the tick number (column T, left out when ``timestamp`` is no)
    and the values of each column with its number of decimals (``decimals`` unless the column
    says otherwise). A relative ``filename`` is relative to the model file's folder; a ``%d``
    in it (or ``%03d`` and so on) is replaced by the file number, which starts at 0.

    When WRITE is connected a line is written only on ticks when its first element is above
    0 (with ``single_trig``, only on ticks when it rises from 0 or below to above 0). When
    NEWFILE is connected, a rise of its first element from 0 or below to above 0 closes the
    file, adds 1 to the file number and opens the next file (the same file again, rewritten,
    when the name has no %d); that tick's line goes into the new file. When ``directory`` is
    set, the files go into a new folder named after it with a number added (``name_0``,
    ``name_1``, ...: the first that does not exist), created at the start of each run."""

    filename = Parameter("output.txt", "the file to write; may contain %d for the file "
                         "number; relative to the model file's folder")
    decimals = Parameter(4, "number of decimals of the columns that do not set their own",
                         type="int")
    timestamp = Parameter(True, "write the tick number as the first column, T")
    directory = Parameter("", "if set, a new folder with this name and a number added is "
                          "created for the files of each run")
    single_trig = Parameter(False, "write only when WRITE rises from 0 to above 0, not on "
                            "every tick it is above 0")
    use_old_format = Parameter(False, "accepted for compatibility and has no effect: the "
                               "header is always written in the NAME/n form that InputFile "
                               "reads")
    NEWFILE = Input("a rise of the first element to above 0 starts a new file", optional=True)
    WRITE = Input("when connected, a line is written only when the first element is above 0",
                  optional=True)

    # --- build time -----------------------------------------------------------------------
    def configure(self):
        self._read_columns(("NEWFILE", "WRITE"), "the values of column", self._build_error)

    def _build_error(self, element, message):
        if element is not None and hasattr(element, "error"):
            return element.error(message)
        return ModelError(message)

    # --- run time -------------------------------------------------------------------------
    def init(self):
        self._file = None
        self._number = 0
        self._last_newfile = False
        self._last_write = False
        self._inputs, value_formats = self._lay_out()
        header, formats = [], []
        if self.timestamp:
            header.append("T/1")
            formats.append("%d")
        for (name, _), x in zip(self._columns, self._inputs):
            header.append(f"{name}/{x.size}")
        formats.extend(value_formats)
        self._header = "\t".join(header) + "\n"
        self._format = "\t".join(formats) + "\n"
        self._folder = self._make_folder()
        if self._folder is not None:
            self._open()

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
        name = _COUNTER.sub(lambda m: ("%" + m.group(1) + "d") % self._number, self.filename)
        return name if os.path.isabs(name) else os.path.join(self._folder, name)

    def _open(self):
        self._close()
        path = self._path()
        try:
            os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
            self._file = open(path, "w", encoding="utf-8")
            self._file.write(self._header)
            self._file.flush()
        except OSError as e:
            self._file = None
            self.fatal_error(f'cannot write output file "{path}": {e.strerror}')

    def tick(self):
        if self.NEWFILE is not None:
            rise = bool(self.NEWFILE.flat[0] > 0)
            if rise and not self._last_newfile and self._folder is not None:
                self._number += 1
                self._open()
            self._last_newfile = rise
        if self.WRITE is not None:
            on = bool(self.WRITE.flat[0] > 0)
            write = on and not (self.single_trig and self._last_write)
            self._last_write = on
            if not write:
                return
        self._write_row()

    def stop(self):
        self._close()
