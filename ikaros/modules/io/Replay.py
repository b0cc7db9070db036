"""Replay: plays one recorded output of an ikaros recording (HDF5) back, tick by tick."""
import json

import numpy as np

from ikaros.module import Module, Output, Parameter, require

from ._files import build_error, resolve

BLOCK_TICKS = 1024     # recorded rows read from the file at a time


class Replay(Module):
    """Plays back one output recorded by ``ikaros --record`` (or ``net.record``), so that a
    model can be developed offline on the data that a robot's sensors produced. ``signal``
    is the address of the recorded output (``Arm.Sensor.OUTPUT``); OUTPUT has its shape.
    On tick k OUTPUT is the k-th recorded row (the first row on tick 0; a recording made
    with ``--record-every`` gives one row per tick here); it is 0 in init. After the last
    row the recording starts again from the first with ``loop``; otherwise the module
    sends end-of-file on the tick that outputs the last row, which stops the run after
    that tick. A recording cut off by a crash is played up to its last flushed row.
    Needs h5py (``pip install 'ikaros[record]'``)."""

    filename = Parameter("", "the recording (.h5); relative to the model file's folder")
    signal = Parameter("", "the address of the recorded output to play, e.g. Arm.DISTANCE")
    loop = Parameter(False, "start again from the first row after the last")
    OUTPUT = Output("the recorded values of the current tick")

    def configure(self):
        h5py = require("h5py", "h5py", extra="record")
        self._path = resolve(self, self.filename)
        try:
            self._file = _open(h5py, self._path)
        except OSError as e:
            raise build_error(self, f'cannot read the recording "{self.filename}": '
                                    f'{e}') from None
        f = self._file
        if f.attrs.get("format") != "ikaros-recording":
            raise build_error(self, f'"{self.filename}" is not an ikaros recording')
        signals = {name: (tuple(shape), start, stop)
                   for name, shape, start, stop in json.loads(f.attrs["signals"])}
        if self.signal not in signals:
            raise build_error(self, f'the recording "{self.filename}" has no signal '
                                    f'"{self.signal}"; it has {", ".join(signals)}')
        self._shape, self._start, self._stop = signals[self.signal]
        self._rows = min(f["data"].shape[0], f["tick"].shape[0])
        if self._rows == 0:
            raise build_error(self, f'the recording "{self.filename}" has no rows')
        self.set_output_shape("OUTPUT", self._shape)

    def init(self):
        self._next = 0                  # the row to output on the next tick
        self._block_first = 0
        self._block = np.zeros((0,), np.float32)
        self._done = False

    def _row(self, k: int) -> np.ndarray:
        if not (self._block_first <= k < self._block_first + self._block.shape[0]):
            first = k - k % BLOCK_TICKS
            last = min(first + BLOCK_TICKS, self._rows)
            self._block = self._file["data"][first:last, self._start:self._stop]
            self._block_first = first
        return self._block[k - self._block_first]

    def tick(self):
        if self._done:
            return
        k = self._next
        self.OUTPUT[...] = self._row(k).reshape(self._shape)
        self._next = k + 1
        if self._next == self._rows:
            if self.loop:
                self._next = 0
            else:
                self._done = True
                self.end_of_file(f'end of the recording "{self.filename}"')

    def stop(self):
        self._file.close()


def _open(h5py, path: str):
    """Open a recording, also one still being written or cut off (SWMR)."""
    try:
        return h5py.File(path, "r")
    except OSError:
        return h5py.File(path, "r", swmr=True)
