"""DynamicMatrixSink: checks what a DynamicMatrixSource sends it, shape and values."""
import numpy as np

from ikaros.dynamic import DynamicArray
from ikaros.module import Input, Parameter

from ikaros.testsupport._internal import InternalModule, first_tick, grown, shape_text


class DynamicMatrixSink(InternalModule):
    """INPUT is fed whole by a DynamicMatrixSource (same ``max_rows`` and ``columns``) over
    a connection of ``delay`` ticks. Every tick it prints ``DYNAMIC tick=t shape=RxC:
    values`` and compares INPUT with what the source output ``delay`` ticks before; a
    difference (or an INPUT that is not dynamic) is a fatal error. At the end it prints
    ``DYNAMIC MATRIX TEST OK`` if every tick matched."""

    max_rows = Parameter(4, "the source's max_rows")
    columns = Parameter(2, "the source's columns")
    delay = Parameter(0, "the connection's delay")
    INPUT = Input("the dynamic matrix")

    def init(self):
        self._ticks = 0
        self._failed = not isinstance(self.INPUT, DynamicArray)
        if self._failed:
            self.fatal_error("DYNAMIC MISMATCH: INPUT is not a dynamic array")

    def tick(self):
        t = self.clock.tick
        got = np.asarray(self.INPUT)
        want = grown(t - int(self.delay), self.max_rows, self.columns,
                     first_tick(self))
        values = " ".join(f"{v:g}" for v in got.reshape(-1).tolist())
        self.print(f"DYNAMIC tick={t} shape={shape_text(got.shape)}: {values}".rstrip())
        self._ticks += 1
        if got.shape != want.shape or not np.array_equal(got, want):
            self._failed = True
            self.fatal_error(f"DYNAMIC MISMATCH at tick {t}: got {got.tolist()}, expected "
                             f"{want.tolist()}")

    def stop(self):
        if self._ticks and not self._failed:
            self.print("DYNAMIC MATRIX TEST OK")
