"""SequenceRecorder: records and plays back sequences of any values."""
import numpy as np

from ikaros.module import Input, Parameter
from ikaros.modules.robot._recording import Recorder


class SequenceRecorder(Recorder):
    """MotionRecorder for any sequence of ``output_size`` values: it records INPUT (its first
    ``output_size`` elements, zero-padded), or, when INPUT is not connected, the values set
    with the ``set`` command (value: the list of values) starting from ``positions``, so a
    sequence of keyframes can be built without a robot. Everything else — modes, TRIG,
    keyframes, interpolation, smoothing, save and load — is as in MotionRecorder."""

    positions = Parameter("", "the values recorded when INPUT is not connected, until changed with set",
                          type="array")
    output_size = Parameter(1, "number of channels")

    INPUT = Input("the values to record", optional=True)

    def channel_count(self):
        return int(self.output_size)

    def init(self):
        self._manual = np.zeros(int(self.output_size))
        positions = np.asarray(self.positions, dtype=np.float64).reshape(-1)[:self._manual.size]
        self._manual[:positions.size] = positions
        super().init()

    def command(self, name, x=0, y=0, value=None):
        if name == "set":
            values = np.asarray(value if value is not None else [x], dtype=np.float64).reshape(-1)
            self._manual[:] = 0.0
            self._manual[:min(values.size, self._manual.size)] = values[:self._manual.size]
            return
        super().command(name, x, y, value)

    def source(self):
        if self.INPUT is None:
            return self._manual.copy()
        values = np.zeros(self._manual.size)
        flat = self.INPUT.reshape(-1)[:values.size]
        values[:flat.size] = flat
        return values
