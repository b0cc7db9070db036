"""Output taps: copies of chosen arena values into the rows of a caller's array, one row per
tick the caller picks (a recording's rows).

``keep(row)`` after a tick asks for that tick's values in ``rows[row]``. With the compiled
tick, the copy is an instruction of the compiled call that starts the next tick (before
anything of that tick runs), so keeping a row costs the kernel thread one store and no call;
``settle()`` makes a copy still pending now (before the rows are read). Without the compiled
tick ``keep`` copies at once (one NumPy gather).
"""
from __future__ import annotations

import numpy as np


class OutputTap:
    """Copies ``block[index]`` into ``rows[r]`` for the rows ``r`` that ``keep`` names."""

    def __init__(self, block: np.ndarray, index: np.ndarray, rows: np.ndarray):
        if rows.ndim != 2 or rows.shape[1] != index.size or rows.dtype != np.float32 \
                or not rows.flags.c_contiguous:
            raise ValueError("a tap's rows are a C-contiguous float32 array of "
                             f"(rows, {index.size}) values")
        self.block = block
        self.index = np.asarray(index, np.int64)
        self.rows = rows
        self.compiled = False           # whether the compiled tick makes the copies
        self._use(np.zeros(1, np.int64))

    def _use(self, pending: np.ndarray) -> None:
        self._pending = pending         # the row kept + 1; 0 when none
        self._mark = memoryview(pending)          # stores in a quarter of NumPy's time

    def keep(self, row: int) -> None:
        """The values as they are now (after a tick) go into ``rows[row]``."""
        if self.compiled:
            self._mark[0] = row + 1
        else:
            np.take(self.block, self.index, out=self.rows[row])

    def settle(self) -> None:
        """Make the copy that ``keep`` left to the next compiled tick now."""
        row = int(self._pending[0]) - 1
        if row >= 0:
            np.take(self.block, self.index, out=self.rows[row])
            self._pending[0] = 0

    def bind(self, pending: np.ndarray) -> None:
        """From now on the compiled tick copies: ``pending`` is the one-element view of its
        index pool where it looks for the row kept."""
        self.settle()
        pending[0] = 0
        self._use(pending)
        self.compiled = True

    def unbind(self) -> None:
        """From now on ``keep`` copies at once."""
        self.settle()
        self._use(np.zeros(1, np.int64))
        self.compiled = False
