"""The start-up steps of a build and the time each took (shown by the web UI)."""
from __future__ import annotations

import contextlib
import time


class StartupSteps:
    """A list of (step, seconds) in the order the steps ran."""

    def __init__(self):
        self.steps: list[tuple[str, float]] = []

    @contextlib.contextmanager
    def step(self, name: str):
        start = time.perf_counter()
        try:
            yield
        finally:
            self.steps.append((name, time.perf_counter() - start))

    def as_list(self) -> list[dict]:
        return [{"step": name, "seconds": seconds} for name, seconds in self.steps]
