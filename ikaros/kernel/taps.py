"""Output taps: copies of chosen arena values into the rows of a caller's array, one row per
tick the caller picks (a recording's rows).

``keep(row)`` after a tick asks for that tick's values in ``rows[row]``. With the compiled
tick, the copy is an instruction of the compiled call that starts the next tick (before
anything of that tick runs), so keeping a row costs the kernel thread one store (a C call);
``settle()`` makes a copy still pending now (before the rows are read). Without the compiled
tick ``keep`` copies at once (one NumPy gather).
"""
from __future__ import annotations

import functools

import numpy as np


NONE = -1          # no row kept


class OutputTap:
    """Copies ``block[index]`` into ``rows[r]`` for the rows ``r`` that ``keep`` names.

    ``keep(row)``: the values as they are now (after a tick) go into ``rows[row]``. With the
    compiled tick it only stores ``row`` where the compiled call looks for it (a C call: no
    Python frame per tick)."""

    def __init__(self, block: np.ndarray, index: np.ndarray, rows: np.ndarray):
        if rows.ndim != 2 or rows.shape[1] != index.size or rows.dtype != np.float32 \
                or not rows.flags.c_contiguous:
            raise ValueError("a tap's rows are a C-contiguous float32 array of "
                             f"(rows, {index.size}) values")
        self.block = block
        self.index = np.asarray(index, np.int64)
        self.rows = rows
        self._pending: np.ndarray | None = None     # where the compiled call looks
        self.keep = self._copy_now

    @property
    def compiled(self) -> bool:
        """Whether the compiled tick makes the copies."""
        return self._pending is not None

    def _copy_now(self, row: int) -> None:
        np.take(self.block, self.index, out=self.rows[row])

    def settle(self) -> None:
        """Make the copy that ``keep`` left to the next compiled tick now."""
        pending = self._pending
        if pending is not None and pending[0] != NONE:
            self._copy_now(int(pending[0]))
            pending[0] = NONE

    def bind(self, pending: np.ndarray) -> None:
        """From now on the compiled tick copies: ``pending`` is the one-element view of its
        index pool where it looks for the row kept."""
        self.settle()
        pending[0] = NONE
        self._pending = pending
        self.keep = functools.partial(memoryview(pending).__setitem__, 0)

    def unbind(self) -> None:
        """From now on ``keep`` copies at once."""
        self.settle()
        self._pending = None
        self.keep = self._copy_now
