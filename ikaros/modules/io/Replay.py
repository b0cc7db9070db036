"""Replay: plays one recorded output of an ikaros recording (HDF5) back, tick by tick."""
import weakref

import numpy as np

from ikaros.module import Module, Parameter, attribute_name, require

from ._files import build_error, resolve
from ._recordingfile import RecordingFile

_warned: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()   # network: files told of


class Replay(Module):
    """Plays back outputs recorded by ``ikaros --record`` (or ``net.record``), so that a
    model can be developed offline on the data that a robot's sensors produced. With
    ``signal``, the address of one recorded output (``Arm.Sensor.OUTPUT``), the module has
    one output, OUTPUT, of its shape. With ``module``, the address of a recorded module
    (``Arm.Sensor``), it has every recorded output of that module, under the same names
    (this is how ``ikaros --replay`` stands in for the modules of a recorded model).

    On tick k the outputs are the k-th recorded row (the first row on tick 0; a recording
    made with ``--record-every`` gives one row per tick here); they are 0 in init. After
    the last row, ``end`` says what happens: ``stop`` sends end-of-file on the tick that
    outputs the last row, which stops the run after that tick; ``loop`` starts again from
    the first row; ``hold`` keeps the last row. The command ``seek`` with x = a row number
    makes that row the next one; ``row`` is the row shown (-1 before the first tick). A
    recording cut off by a crash is played up to its last flushed row. A damaged recording
    is refused when the model is built, naming the damage, or, when only its end is
    missing, played up to its last whole chunk with a warning (once per file); values
    that fail the file's checksums stop the run with an error naming the rows, never
    played. Needs h5py (``pip install 'ikaros[record]'``)."""

    filename = Parameter("", "the recording (.h5); relative to the model file's folder")
    signal = Parameter("", "the address of the recorded output to play as OUTPUT, e.g. "
                       "Arm.DISTANCE")
    module = Parameter("", "instead of signal: the address of a recorded module, whose "
                           "recorded outputs are all played, under their own names")
    end = Parameter("stop", "after the last row: stop the run, loop to the first row, or "
                    "hold the last row", options="stop/loop/hold")

    def configure(self):
        require("h5py", "h5py", extra="record")
        self._path = resolve(self, self.filename)
        try:
            self._file = RecordingFile(self._path)
        except (OSError, ValueError) as e:
            raise build_error(self, str(e)) from None
        try:
            self._choose(self._file)
        except BaseException:
            self._file.close()
            raise

    def _choose(self, f: RecordingFile) -> None:
        """The outputs: the recorded signals chosen by ``signal`` or ``module``."""
        signals = {name: (shape, start, stop) for name, shape, start, stop in f.signals}
        if bool(self.signal) == bool(self.module):
            raise build_error(self, "give either signal (one recorded output) or module "
                                    "(all recorded outputs of a module)")
        if self.signal:
            if self.signal not in signals:
                raise build_error(self, f'the recording "{self.filename}" has no signal '
                                        f'"{self.signal}"; it has {", ".join(signals)}')
            chosen = {"OUTPUT": signals[self.signal]}
        else:
            prefix = self.module + "."
            chosen = {name[len(prefix):]: where for name, where in signals.items()
                      if name.startswith(prefix) and "." not in name[len(prefix):]}
            if not chosen:
                raise build_error(self, f'the recording "{self.filename}" has no outputs '
                                        f'of module "{self.module}"')
        self._rows = f.rows
        self._block_ticks = f.chunk_rows     # a chunk of the file, decompressed once
        if self._rows == 0:
            raise build_error(self, f'the recording "{self.filename}" has no rows')
        self._start = min(start for _, start, _ in chosen.values())
        self._stop = max(stop for _, _, stop in chosen.values())
        self._ports = [(attribute_name(name), shape, start - self._start, stop - self._start)
                       for name, (shape, start, stop) in chosen.items()]
        for name, (shape, _, _) in chosen.items():
            self.add_output(name, shape, description="the recorded values of the current tick")

    def init(self):
        network = getattr(self._ik_notify, "__self__", None)
        told = _warned.setdefault(network, set()) if network is not None else set()
        if self._file.damage and self._path not in told:
            told.add(self._path)
            self.warning(self._file.damage)
        self.row = -1                   # the row shown
        self._next = 0                  # the row to output on the next tick
        self._block_first = 0
        self._block = np.zeros((0,), np.float32)
        self._done = False

    def _row(self, k: int) -> np.ndarray:
        if not (self._block_first <= k < self._block_first + self._block.shape[0]):
            first = k - k % self._block_ticks
            last = min(first + self._block_ticks, self._rows)
            self._block = self._file.read("data", first, last,
                                          slice(self._start, self._stop))
            self._block_first = first
        return self._block[k - self._block_first]

    def tick(self):
        if self._done:
            return
        k = self.row = self._next
        row = self._row(k)
        for attribute, shape, start, stop in self._ports:
            getattr(self, attribute)[...] = row[start:stop].reshape(shape)
        self._next = k + 1
        if self._next == self._rows:
            if self.end == "loop":
                self._next = 0
            elif self.end == "hold":
                self._next = k
            else:
                self._done = True
                self.end_of_file(f'end of the recording "{self.filename}"')

    def command(self, name, x=0, y=0, value=None):
        if name == "seek":
            self._next = min(max(int(x), 0), self._rows - 1)
            self._done = False

    def stop(self):
        self._file.close()

