"""The task watchdog (top-group ``task_timeout``): a tick that runs longer than the timeout
is reported with the module that was running, and the run stops once that tick has
finished (no module is interrupted mid-tick; every module's stop() runs after it).

The watchdog is a thread that looks at the running threads' stacks a few times per
timeout, so it adds nothing to a tick: the kernel marks no start or end of a tick or of a
module call for it. A compiled stretch of modules is one call and is measured as a whole.
"""
from __future__ import annotations

import sys
import threading
import time
import weakref

from .compiled.plan import CompiledRun

POLLS_PER_TIMEOUT = 10
LONGEST_POLL = 0.1          # seconds between two looks, at most


def task_timeout(text: str | None, error) -> float | None:
    """The ``task_timeout`` setting in seconds, or None when it is unset or 0 (off).
    ``error(message)`` makes the error for a bad value."""
    if text in (None, ""):
        return None
    try:
        value = float(text)
    except ValueError:
        value = float("nan")
    if not value >= 0 or value == float("inf"):
        raise error(f'task_timeout="{text}" must be a number of seconds >= 0 (0: off)')
    return value or None


class Watchdog:
    """Watches the ticks of one network. ``tick_code`` is the code of the network's tick
    method: a thread whose stack holds it for this network is running a tick."""

    def __init__(self, net, timeout: float, tick_code):
        self.timeout = timeout
        self.poll = min(LONGEST_POLL, timeout / POLLS_PER_TIMEOUT)
        self._net = weakref.ref(net)
        self._tick_code = tick_code
        self._modules = {id(inst.module): inst.path for inst in net.schedule}
        self._done = threading.Event()
        self._seen = None           # (tick, when first seen running)
        self._reported = None       # the tick reported as too long
        self._thread = threading.Thread(target=self._watch, name="ikaros-watchdog",
                                        daemon=True)
        self._thread.start()

    def close(self) -> None:
        """Stop watching (the run has ended)."""
        self._done.set()
        if self._thread is not threading.current_thread():
            self._thread.join()

    def _watch(self) -> None:
        while not self._done.wait(self.poll):
            net = self._net()
            if net is None:
                return
            self.check(net, time.perf_counter())
            del net

    def check(self, net, now: float) -> None:
        """One look: note the tick under way, and report it once when it is too long."""
        frames = sys._current_frames()
        runner = self._tick_thread(net, frames)
        if runner is None:
            self._seen = None
            return
        tick = net.tick
        if self._seen is None or self._seen[0] != tick:
            self._seen = (tick, now)
            return
        if now - self._seen[1] <= self.timeout or self._reported == tick:
            return
        self._reported = tick
        where = self._running_module(frames, runner) or "the kernel"
        # the tick as the model numbers it (the first is 1 in an Ikaros 3 file)
        net.time_out(where, f"tick {tick + net.first_tick} exceeded task_timeout ({self.timeout:g} s) in "
                            f"{where}; waiting for the tick to finish before stopping",
                     f"the tick timed out after {self.timeout:g} s (task_timeout)")

    def _tick_thread(self, net, frames: dict) -> int | None:
        """The id of the thread running a tick of ``net``, or None."""
        for ident, frame in frames.items():
            while frame is not None:
                if frame.f_code is self._tick_code and frame.f_locals.get("self") is net:
                    return ident
                frame = frame.f_back
        return None

    def _running_module(self, frames: dict, runner: int) -> str | None:
        """The module whose tick is running: in the tick's thread, or in a lane."""
        lanes = {t.ident for t in threading.enumerate() if t.name.startswith("ikaros-lane")}
        for ident in [runner] + sorted(lanes):
            frame = frames.get(ident)
            while frame is not None:
                owner = frame.f_locals.get("self")
                path = self._modules.get(id(owner))
                if path is not None:
                    return path
                if isinstance(owner, CompiledRun):
                    members = owner.members
                    return (f"the compiled stretch {members[0].path} ... {members[-1].path} "
                            f"({len(members)} modules)")
                frame = frame.f_back
        return None

