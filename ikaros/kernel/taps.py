"""Output taps: copies of chosen arena values into successive rows of a caller's array (a
recording's ring of blocks), every ``every``-th tick, with no Python per tick kept.

At the start of every tick (before anything of it runs) the tap looks at the values of the
tick just done: when that tick is due, they go into the next row of the room the caller gave
(``give(start, end)``) and the tick's number into ``ticks``. With the compiled tick this is an
instruction of the compiled call (ops.TAP), whose state is an int64 array the tap shares
with it; without it, ``step()`` does the same with NumPy. The caller is called back
(``on_signal``) only when the room is full or it asked for it (``request()``, from any
thread): once a block, and once a second for a partial flush. ``settle()`` takes the row of
the tick just done now (before the rows are read at the end).
"""
from __future__ import annotations

from typing import Callable

import numpy as np

from .compiled.ops import (TAP_DUE as DUE, TAP_END as END, TAP_EVERY as EVERY,
                           TAP_ROW as ROW, TAP_SIGNAL as SIGNAL, TAP_STATE as STATE,
                           TAP_TICK as TICK)


class OutputTap:
    """Keeps ``block[index]`` in ``rows[state[ROW]]`` (and the tick in ``ticks``) after every
    due tick, from tick ``first`` on; see the module docstring."""

    def __init__(self, block: np.ndarray, index: np.ndarray, rows: np.ndarray, first: int,
                 every: int, on_signal: Callable[[], None]):
        if rows.ndim != 2 or rows.shape[1] != index.size or rows.dtype != np.float32 \
                or not rows.flags.c_contiguous:
            raise ValueError("a tap's rows are a C-contiguous float32 array of "
                             f"(rows, {index.size}) values")
        self.block = block
        self.index = np.asarray(index, np.int64)
        self.rows = rows
        self.on_signal = on_signal
        state = np.zeros(STATE, np.int64)
        state[[TICK, DUE, EVERY]] = first - 1, first, every
        # (state, ticks) swapped in one assignment, so another thread sees a matching pair
        self.views = (state, np.zeros(len(rows), np.int64))
        self.compiled = False         # whether the compiled tick takes the rows

    @property
    def state(self) -> np.ndarray:
        return self.views[0]

    @property
    def ticks(self) -> np.ndarray:
        """The tick of each row kept."""
        return self.views[1]

    def give(self, start: int, end: int) -> None:
        """Rows ``start`` to ``end - 1`` are free to fill."""
        state = self.state
        state[ROW], state[END] = start, end

    def stop(self) -> None:
        """Keep no more rows and call back no more."""
        state = self.state
        state[DUE], state[ROW], state[END], state[SIGNAL] = np.iinfo(np.int64).max // 2, 0, -1, 0

    def request(self) -> None:
        """Call ``on_signal`` at the start of the next tick (safe from any thread)."""
        self.views[0][SIGNAL] = 1

    def _take(self) -> bool:
        """Keep the arena's values when due; whether to call back (as the compiled TAP)."""
        state = self.state
        t, row = state[TICK], state[ROW]
        if t >= state[DUE] and row < state[END]:
            np.take(self.block, self.index, out=self.rows[row])
            self.ticks[row] = t
            state[ROW] = row = row + 1
            state[DUE] = t + state[EVERY]
        return row == state[END] or state[SIGNAL] != 0

    def step(self) -> None:
        """At the start of a tick (without the compiled tick)."""
        signal = self._take()
        self.state[TICK] += 1
        if signal:
            self.on_signal()

    def settle(self) -> None:
        """Keep the values of the tick just done now, when due (between ticks)."""
        self._take()

    def bind(self, view: np.ndarray, tick: int) -> None:
        """From now on the compiled tick takes the rows: ``view`` is the part of its index
        pool that holds the state and ticks; ``tick`` the one the arena holds."""
        state, ticks = self.views
        view[:STATE], view[STATE:] = state, ticks
        view[TICK] = tick
        self.views = (view[:STATE], view[STATE:])
        self.compiled = True

    def unbind(self) -> None:
        """From now on ``step()`` takes the rows."""
        if self.compiled:
            self.views = (self.state.copy(), self.ticks.copy())
            self.compiled = False
