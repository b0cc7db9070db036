"""What the kernel tells modules about the run: its mode, its stop tick, how many modules
and classes it has and how long the last tick took. Modules read it as ``clock.run``
(System publishes it)."""
from __future__ import annotations

import time

from .control import FASTFORWARD, PAUSE, PLAY, REALTIME, STEP, STOP

# Ikaros 3's run-mode codes (KERNEL.md §1.2): 1 stop, 2 pause, 3 play, 4 realtime,
# 5 fast forward; a tick stepped from pause runs in pause
RUN_MODE_CODES = {STOP: 1, PAUSE: 2, STEP: 2, PLAY: 3, REALTIME: 4, FASTFORWARD: 5}


class RunFacts:
    """A read-only view of a network's run, for modules."""

    def __init__(self, net):
        self._net = net
        self.built = time.perf_counter()
        self.module_count = len(net.modules)
        self.class_count = len({type(inst.module).__name__ for inst in net.schedule})

    @property
    def mode(self) -> int:
        """Ikaros 3's code of the run mode: a network stepped from Python, without the run
        controller, runs as in play (3)."""
        controller = self._net._controller
        return RUN_MODE_CODES.get(controller.state, 3) if controller is not None else 3

    @property
    def stop_tick(self) -> int | None:
        """The model's ``stop`` (the number of ticks it runs), or None without one."""
        stop = self._net.stop_tick
        return stop if stop is not None and stop >= 0 else None

    @property
    def ticks_done(self) -> int:
        """Ticks completed before the current one."""
        return self._net.tick

    @property
    def tick_time_usage(self) -> float:
        """Seconds the last completed tick took to compute."""
        return self._net.timing.last_spent

    @property
    def uptime(self) -> float:
        """Seconds since the network was built."""
        return time.perf_counter() - self.built
