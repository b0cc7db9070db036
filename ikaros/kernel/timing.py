"""Timing: precise waiting for real-time deadlines, and the run's timing figures."""
from __future__ import annotations

import os
import time

import numpy as np

LAG_HISTORY = 4096  # ticks of lag kept for the 99th percentile


class Waiter:
    """Waits for real-time deadlines: sleeps, then spins for the last stretch (the margin).

    How late ``time.sleep`` wakes up depends on the machine and its load, so the margin
    follows it: it rises at once to a late wake-up seen (plus ``SLACK``), falls slowly
    while wake-ups are prompt, and falls slowly too while it is so large that no sleep is
    taken, so that it is tried again. It stays between ``MIN_MARGIN`` and ``MAX_MARGIN``.
    """

    MIN_MARGIN = 0.0002
    MAX_MARGIN = 0.002
    SLACK = 0.00005
    FALL = 0.01            # fraction of the distance to a prompt wake-up's need, per sleep
    UNUSED_FALL = 0.998    # factor per wait taken without sleeping

    def __init__(self, margin: float = 0.0005):
        self.margin = margin

    def wait_until(self, deadline: float) -> float:
        """Return once ``perf_counter() >= deadline``; returns the time spent waiting."""
        perf = time.perf_counter
        start = perf()
        request = deadline - start - self.margin
        if request > 0:
            time.sleep(request)
            self._woke(perf() - start - request)
        elif request > self.MIN_MARGIN - self.margin:
            self.margin = max(self.MIN_MARGIN, self.margin * self.UNUSED_FALL)
        while perf() < deadline:
            pass
        return perf() - start

    def _woke(self, overshoot: float) -> None:
        need = overshoot + self.SLACK
        if need > self.margin:
            self.margin = min(self.MAX_MARGIN, need)
        else:
            self.margin = max(self.MIN_MARGIN, self.margin - (self.margin - need) * self.FALL)


class Timing:
    """Figures of a run, updated once per tick at almost no cost."""

    def __init__(self):
        self.cores = os.cpu_count() or 1
        self.reset()

    def reset(self) -> None:
        now = time.perf_counter()
        self.started = now
        self.ticks = 0
        self.last_start = None
        self.actual_duration = 0.0
        self.lag = 0.0
        self.lag_max = 0.0
        self.lags = np.zeros(LAG_HISTORY)
        self.lag_count = 0
        self.idle = 0.0
        self.busy = 0.0
        self.last_spent = 0.0           # seconds the last tick took
        self.resyncs = 0
        self._cpu_sample = (now, time.process_time())
        self._sampled = False
        self.cpu_usage = 0.0

    def tick_started(self, now: float, lag: float | None) -> None:
        if self.last_start is not None:
            self.actual_duration = now - self.last_start
        self.last_start = now
        if lag is not None:
            self.lag = lag
            if lag > self.lag_max:
                self.lag_max = lag
            self.lags[self.lag_count % LAG_HISTORY] = lag
            self.lag_count += 1

    def tick_done(self, spent: float) -> None:
        self.ticks += 1
        self.busy += spent
        self.last_spent = spent

    def figures(self) -> dict:
        """The figures now (CPU usage is measured since the previous call)."""
        now = time.perf_counter()
        cpu = time.process_time()
        wall0, cpu0 = self._cpu_sample
        if now - wall0 > 0.05 or not self._sampled:
            self._sampled = True
            self.cpu_usage = (cpu - cpu0) / ((now - wall0) * self.cores)
            self._cpu_sample = (now, cpu)
        elapsed = now - self.started
        n = min(self.lag_count, LAG_HISTORY)
        return {
            "elapsed": elapsed,
            "ticks_per_second": self.ticks / elapsed if elapsed > 0 else 0.0,
            "actual_tick_duration": self.actual_duration,
            "lag": self.lag,
            "lag_max": self.lag_max,
            "lag_p99": float(np.percentile(self.lags[:n], 99)) if n else 0.0,
            "resyncs": self.resyncs,
            "cpu_usage": self.cpu_usage,        # of all cores (cpu_cores) together
            "cpu_cores": self.cores,
            "idle": self.idle / elapsed if elapsed > 0 else 0.0,
            "busy": self.busy,
        }
