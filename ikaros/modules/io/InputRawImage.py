"""InputRawImage: reads 8-bit raw gray images."""

import numpy as np

from ikaros.module import Module, Output, Parameter

from ._files import build_error, has_counter, numbered, resolve
from ._images import from_uint8


class InputRawImage(Module):
    """Reads a raw gray image: a file of exactly ``size_x`` × ``size_y`` bytes, one byte per
    pixel row by row, with no header. OUTPUT is the image (size_y rows, size_x columns) with
    the bytes 0..255 scaled to 0..1. A ``%d`` in ``filename`` (or ``%02d`` and so on) reads
    a numbered sequence of ``filecount`` files. The first image is on OUTPUT from init;
    every image is shown for ``repeats`` ticks, the sequence is shown ``iterations`` times
    (0 means forever) and then the module sends end-of-file, which stops the run, and keeps
    the last image. A later file that cannot be read or has the wrong size gives a warning
    and the previous image stays."""

    size_x = Parameter(None, "columns of the image (the file has size_x × size_y bytes)",
                       type="int")
    size_y = Parameter(None, "rows of the image", type="int")
    filename = Parameter("", "the raw file; %d (or %02d and so on) is replaced by the file "
                         "number 0, 1, ... to read a sequence; relative to the model file's "
                         "folder")
    filecount = Parameter(1, "number of files in the sequence", type="int")
    iterations = Parameter(0, "how many times the sequence is shown before end-of-file stops "
                           "the run; 0 means forever (the Ikaros 2 default, inf)", type="int")
    repeats = Parameter(1, "number of ticks each image is shown", type="int")

    OUTPUT = Output("the image, (size_y, size_x), in 0..1",
                    size_param_x="size_x", size_param_y="size_y")

    def configure(self):
        if not self.size_x or not self.size_y or self.size_x < 1 or self.size_y < 1:
            raise build_error(self, "InputRawImage needs size_x and size_y (a raw file has "
                              "no header that gives its size)")
        if not self.filename:
            raise build_error(self, "InputRawImage needs a filename")
        if self.filecount < 1:
            raise build_error(self, "filecount must be at least 1")
        try:
            self._first = self._read(self._path(0))
        except (OSError, ValueError) as e:
            raise build_error(self, f"{getattr(e, 'strerror', None) or e}") from None

    def _path(self, index):
        name = numbered(self.filename, index) if has_counter(self.filename) else self.filename
        return resolve(self, name)

    def _read(self, path):
        n = self.size_x * self.size_y
        try:
            data = np.fromfile(path, dtype=np.uint8)
        except OSError as e:
            raise OSError(e.errno, f'cannot read raw image "{path}": {e.strerror}') from None
        if data.size != n:
            raise ValueError(f'raw image "{path}" has {data.size} bytes; size_x × size_y is '
                             f'{n}')
        return from_uint8(data).reshape(self.size_y, self.size_x)

    def init(self):
        self.OUTPUT[...] = self._first
        self._first = None
        self._index = 0
        self._warned = set()

    def tick(self):
        repeats = max(1, self.repeats)
        step, within = divmod(self.clock.tick, repeats)
        iteration, index = divmod(step, self.filecount)
        if self.iterations > 0 and iteration >= self.iterations:
            return
        if index != self._index:
            path = self._path(index)
            try:
                self.OUTPUT[...] = self._read(path)
            except (OSError, ValueError) as e:
                if path not in self._warned:
                    self._warned.add(path)
                    self.warning(f"{getattr(e, 'strerror', None) or e}; the previous image "
                                 f"is kept")
            self._index = index
        if self.iterations > 0 and iteration == self.iterations - 1 and \
                index == self.filecount - 1 and within == repeats - 1:
            self.end_of_file("end of the raw image sequence")
