"""What a sweep shows while it runs: on a terminal, a bar over the runs and one per run in
progress (its ticks done of its ticks, tqdm), and the report of each failed run.

Runs in local processes write the ticks they have done into shared memory
(``TickCounters``), which a thread of the sweep's process shows; runs on Ray show in the
bar over the runs only."""
from __future__ import annotations

import multiprocessing
import sys
import threading

from .progress import terminal_rows

INTERRUPTED = "interrupted"
UPDATES_PER_SECOND = 4
CHUNKS = 200            # a run reports its ticks this many times (it runs in as many steps)


class TickCounters:
    """The ticks done by each run of a sweep, in memory shared with its worker processes
    (made before they start)."""

    def __init__(self, runs: int, context=None):
        self.values = (context or multiprocessing).Array("q", max(runs, 1), lock=False)

    def reporter(self, run: int):
        """A function that records the ticks done by ``run``."""
        values = self.values

        def report(ticks: int) -> None:
            values[run] = ticks
        return report


def run_in_steps(net, ticks: int, report=None) -> None:
    """``net.run(ticks=ticks)``, in about CHUNKS steps when ``report`` is given, telling it
    the network's tick after each."""
    if report is None:
        net.run(ticks=ticks)
        return
    step = max(1, ticks // CHUNKS)
    while net.tick < ticks and not net.stopped:
        net.run(ticks=min(step, ticks - net.tick))
        report(net.tick)


class Reporter:
    """The bars of a sweep (when ``progress``, or None and stderr is a terminal) and its
    failures (``on_failure(row)``, printed by default). ``counters``: the TickCounters the
    runs write into, for a bar per run in progress."""

    def __init__(self, total: int, progress: bool | None, on_failure,
                 counters: TickCounters | None = None):
        self.on_failure = on_failure or _print_failure
        self.rows: list[dict] = []      # of the runs done, and those cut off
        self.bar = None
        self.counters = counters
        self._runs: dict[int, tuple] = {}       # run index: (its bar, its line)
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._thread = None
        if progress is None:
            progress = sys.stderr.isatty()
        if not progress:
            return
        try:
            from tqdm import tqdm
        except ImportError:
            print("ikaros sweep: pip install tqdm (or 'ikaros[progress]') for progress bars",
                  file=sys.stderr)
            return

        class Bar(tqdm):
            monitor_interval = 0        # no monitor thread: workers are forked
        self._bar_class = Bar
        self.bar = Bar(total=total, unit="run", file=sys.stderr, nrows=terminal_rows())
        if counters is not None:
            self._thread = threading.Thread(target=self._show_runs, name="ikaros-sweep-bars",
                                            daemon=True)
            self._thread.start()

    def started(self, spec) -> None:
        """A run was handed to a worker: its bar appears."""
        if self.bar is None or self.counters is None:
            return
        with self._lock:
            if spec.index in self._runs:
                return
            used = {line for _, line in self._runs.values()}
            line = next(k for k in range(1, len(used) + 2) if k not in used)
            self.counters.values[spec.index] = 0
            bar = self._bar_class(total=spec.ticks, unit="tick", desc=f"run {spec.index}",
                                  position=line, leave=False, file=sys.stderr,
                                  nrows=terminal_rows())
            self._runs[spec.index] = (bar, line)

    def done(self, row: dict) -> None:
        self.rows.append(row)
        with self._lock:
            bar, _ = self._runs.pop(row["run"], (None, 0))
            if bar is not None:
                bar.update(row.get("ticks", 0) - bar.n)
                bar.close()
        if row["status"] == INTERRUPTED:
            return
        if row["status"] != "ok":
            self.on_failure(row)
        if self.bar is not None:
            self.bar.update(1)

    def _show_runs(self) -> None:
        while not self._stop.wait(1 / UPDATES_PER_SECOND):
            with self._lock:
                for run, (bar, _) in self._runs.items():
                    ticks = self.counters.values[run]
                    if ticks > bar.n:
                        bar.update(ticks - bar.n)

    def close(self) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join()
        with self._lock:
            for bar, _ in self._runs.values():
                bar.close()
            self._runs.clear()
        if self.bar is not None:
            self.bar.close()


def _print_failure(row: dict) -> None:
    settings = ", ".join(f"{k}={v}" for k, v in row.items()
                         if k not in ("run", "status", "error", "ticks", "seconds",
                                      "recording", "attempts"))
    print(f"ikaros sweep: run {row['run']} ({settings}) failed after {row['attempts']} "
          f"attempt(s): {row['error']}", file=sys.stderr, flush=True)
