"""A progress bar for long batch runs (tqdm): ticks done, ticks per second, time left."""
from __future__ import annotations

import os
import sys
import time

UPDATES_PER_SECOND = 4


def _columns(stream) -> int:
    """The terminal's width (80 when it does not say, as a new pseudo-terminal)."""
    try:
        return os.get_terminal_size(stream.fileno()).columns or 80
    except (OSError, ValueError, AttributeError):
        return 80


def terminal_rows(stream=None) -> int:
    """The terminal's height, 24 when it does not say (a new pseudo-terminal says 0 rows,
    and tqdm draws no bar at all on a terminal it believes has none)."""
    stream = stream if stream is not None else sys.stderr
    try:
        return os.get_terminal_size(stream.fileno()).lines or 24
    except (OSError, ValueError, AttributeError):
        return 24


class Progress:
    """Shows a run's progress on ``stream`` (stderr) while ``net`` runs; the bar is only
    shown when ``stream`` is a terminal. Use as a context manager around the run."""

    def __init__(self, net, total: int | None, stream=None):
        self.net = net
        self.total = total
        self.stream = stream if stream is not None else sys.stderr
        self._bar = None
        self._count = 0
        self._every = 1          # ticks between looks at the clock, adapted to the speed
        self._shown = 0
        self._last = 0.0

    @staticmethod
    def wanted(stream=None, quiet: bool = False) -> bool:
        """Whether a bar is shown: on a terminal, and not when quiet."""
        stream = stream if stream is not None else sys.stderr
        return not quiet and hasattr(stream, "isatty") and stream.isatty()

    def __enter__(self):
        try:
            from tqdm import tqdm
        except ImportError:           # an optional extra: say what gives the bar
            print("ikaros: pip install tqdm (or 'ikaros[progress]') for a progress bar",
                  file=self.stream)
            return self
        self._bar = tqdm(total=self.total, unit="tick", file=self.stream,
                         ncols=_columns(self.stream), nrows=terminal_rows(self.stream),
                         smoothing=0.1,
                         mininterval=1 / UPDATES_PER_SECOND)
        self._start = self.net.tick
        self._last = time.perf_counter()
        self.net.controller.tick_hooks.append(self.hook)
        return self

    def hook(self) -> None:
        self._count += 1
        if self._count >= self._every:
            self._count = 0
            now = time.perf_counter()
            elapsed = now - self._last
            # look at the clock about 20 times per update
            self._every = max(1, min(100_000, int(self._every / max(elapsed, 1e-6)
                                                  / (20 * UPDATES_PER_SECOND))))
            self._last = now
            self._show()

    def _show(self) -> None:
        done = self.net.tick - self._start
        self._bar.update(done - self._shown)
        self._shown = done

    def __exit__(self, *exc):
        if self._bar is not None:
            hooks = self.net.controller.tick_hooks
            if self.hook in hooks:
                hooks.remove(self.hook)
            self._show()
            self._bar.close()
