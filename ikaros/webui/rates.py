"""Tick rates for the status: over the last second, and the mean over the time the run ran.

The kernel's own ``ticks_per_second`` divides every tick by the time since the run began,
paused time included, so after a pause it shows far less than the model runs at. The web UI
samples ``(time, tick, running)`` whenever it builds a status (about 5 times a second while
a client is connected, and on every run-state change) and measures from those samples.
"""
from __future__ import annotations

import collections
import time

RUNNING = ("play", "realtime", "step", "fastforward")
WINDOW = 1.0      # seconds: "ticks/s" is the rate over the last second


class TickRate:
    """Rates from samples of the tick count; cheap, no work in the kernel's thread."""

    def __init__(self, window: float = WINDOW):
        self.window = window
        self.reset()

    def reset(self) -> None:
        self.samples: collections.deque = collections.deque()   # (time, tick)
        self.last: tuple[float, int, bool] | None = None
        self.run_time = 0.0
        self.run_ticks = 0

    def sample(self, tick: int, running: bool, now: float | None = None,
               tick_duration: float = 0.0) -> dict:
        """Record a sample; returns ``{"ticks_per_second", "ticks_per_second_mean",
        "actual_tick_duration_mean"}`` (``None`` where nothing is known: the rate and the
        duration while not running, the mean before anything ran). Within 50 ms of a start
        the rate is 1 / ``tick_duration`` (the last tick's measured duration), when that is
        known. ``actual_tick_duration_mean`` is the mean time from one tick's start to the
        next over the same window: 1 / the rate."""
        now = time.perf_counter() if now is None else now
        if self.last is not None and tick < self.last[1]:
            self.reset()                    # a new network (apply, open) starts at 0
        if self.last is not None:
            t0, tick0, was_running = self.last
            if was_running:                 # changes of state are sampled as they happen
                self.run_time += now - t0
                self.run_ticks += tick - tick0
            if running and not was_running:
                self.samples.clear()        # the window starts when the run resumed
        self.last = (now, tick, running)
        self.samples.append((now, tick))
        while len(self.samples) > 2 and self.samples[1][0] <= now - self.window:
            self.samples.popleft()          # keep one sample at least a window old
        rate = None
        if running:
            t0, tick0 = self.samples[0]
            if now - t0 > 0.05:
                rate = (tick - tick0) / (now - t0)
            elif tick_duration > 0:
                rate = 1.0 / tick_duration
        mean = self.run_ticks / self.run_time if self.run_time > 0.05 else None
        return {"ticks_per_second": rate, "ticks_per_second_mean": mean,
                "actual_tick_duration_mean": 1.0 / rate if rate else None}
