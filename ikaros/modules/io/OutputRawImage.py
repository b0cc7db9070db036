"""OutputRawImage: writes images as 8-bit raw files."""
import numpy as np

from ikaros.module import Input, Module, Parameter

from ._files import build_error, numbered, resolve


class OutputRawImage(Module):
    """Writes INPUT to a raw file on every tick: each value times ``scale`` (255 by default,
    so 0..1 becomes 0..255), rounded to the nearest integer and clipped to 0..255 (with a
    warning once), one byte per element in row-major order with no header, so a
    (rows, cols) image gives rows × cols bytes and a (3, rows, cols) colour image its red,
    green and blue planes one after the other. The file name may hold ``%d`` (or ``%02d``
    and so on), replaced by the file number, ``offset`` plus the number of ticks so far;
    without it every tick overwrites the same file. Nothing is written on the first
    ``suppress`` ticks (their numbers are skipped). A file that cannot be written gives a
    warning and the run goes on."""

    filename = Parameter("", "the file to write; %d (or %02d and so on) is replaced by the "
                         "file number; relative to the model file's folder or the "
                         "user-data folder (ikaros -u)")
    scale = Parameter(255.0, "factor each value is multiplied by before it is stored as a "
                      "byte 0..255")
    suppress = Parameter(0, "number of initial ticks on which nothing is written",
                         type="int")
    offset = Parameter(0, "value added to the file number", type="int")

    INPUT = Input("the image to write, values 0..1 with the default scale")

    def configure(self):
        if not self.filename:
            raise build_error(self, "OutputRawImage needs a filename")

    def init(self):
        self._count = 0
        self._warned_range = False
        self._failing = False
        self._scaled = np.zeros(self.INPUT.shape, dtype=np.float32)

    def tick(self):
        number = self.offset + self._count
        self._count += 1
        if self._count <= self.suppress:
            return
        np.multiply(self.INPUT, np.float32(self.scale), out=self._scaled)
        np.nan_to_num(self._scaled, copy=False, nan=0.0)
        np.rint(self._scaled, out=self._scaled)
        if not self._warned_range and (self._scaled.min() < 0 or self._scaled.max() > 255):
            self._warned_range = True
            self.warning("some values are outside 0..255 after scaling and are clipped "
                         "(this warning is given once)")
        data = np.clip(self._scaled, 0, 255).astype(np.uint8)
        path = resolve(self, numbered(self.filename, number), write=True)
        try:
            data.tofile(path)
        except OSError as e:
            if not self._failing:
                self.warning(f'cannot write raw image "{path}": {e.strerror}')
            self._failing = True
        else:
            self._failing = False
