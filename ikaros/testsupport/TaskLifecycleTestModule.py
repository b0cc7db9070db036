"""TaskLifecycleTestModule: prints its life cycle and fails on demand."""
import time

from ikaros.module import Output, Parameter

from ikaros.testsupport._internal import InternalModule


class TaskLifecycleTestModule(InternalModule):
    """Prints ``INIT``, ``TICK_START tick=t`` and ``TICK_END tick=t``
    around each tick, and ``STOP after tick=t`` (the last tick completed, -1 if none)
    when the run ends. It can fail on demand: ``fail_in`` init, tick or stop, by raising an
    exception (``how`` = raise) or by a fatal error notification (``how`` = fatal), with the
    message ``<PHASE>_FATAL <name>``; in tick only on tick ``fail_at_tick``. OUTPUT is the
    number of ticks completed. With ``sleep_in_tick`` > 0 it sleeps that many seconds in
    its tick (between TICK_START and TICK_END) on tick ``sleep_at_tick`` (-1: every tick)."""

    fail_in = Parameter("none", "where to fail", options="none,init,tick,stop")
    how = Parameter("raise", "how to fail", options="raise,fatal")
    fail_at_tick = Parameter(0, "the tick on which tick fails", type="int")
    sleep_in_tick = Parameter(0.0, "seconds to sleep in tick", type="float")
    sleep_at_tick = Parameter(-1, "the tick on which it sleeps (-1: every tick)", type="int")
    OUTPUT = Output("ticks completed", shape="1")

    def _fail(self, phase):
        message = f"{phase.upper()}_FATAL {self.name}"
        if self.how == "fatal":
            self.fatal_error(message)
        else:
            raise RuntimeError(message)

    def init(self):
        self._last = -1
        self.print("INIT")
        if self.fail_in == "init":
            self._fail("init")

    def tick(self):
        t = self.clock.tick
        self.print(f"TICK_START tick={t}")
        if self.fail_in == "tick" and t == self.fail_at_tick:
            self._fail("tick")
        if self.sleep_in_tick > 0 and self.sleep_at_tick in (-1, t):
            time.sleep(self.sleep_in_tick)
        self.OUTPUT[0] += 1
        self._last = t
        self.print(f"TICK_END tick={t}")

    def stop(self):
        self.print(f"STOP after tick={self._last}")
        if self.fail_in == "stop":
            self._fail("stop")
