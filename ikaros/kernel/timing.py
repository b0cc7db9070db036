"""Timing: precise waiting for real-time deadlines, and the run's timing figures."""
from __future__ import annotations

import os
import time

import numpy as np

SPIN = 0.0005      # seconds before a deadline spent spinning instead of sleeping
LAG_HISTORY = 4096  # ticks of lag kept for the 99th percentile


def wait_until(deadline: float) -> float:
    """Sleep, then spin for the last stretch, until ``perf_counter() >= deadline``.
    Returns the time spent waiting."""
    start = time.perf_counter()
    remaining = deadline - start
    if remaining > SPIN:
        time.sleep(remaining - SPIN)
    while time.perf_counter() < deadline:
        pass
    return time.perf_counter() - start


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
            "cpu_usage": self.cpu_usage,
            "idle": self.idle / elapsed if elapsed > 0 else 0.0,
            "busy": self.busy,
        }
