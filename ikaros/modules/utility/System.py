"""System: the kernel's clock, the run's state and its speed as outputs a model can use."""
import collections
import os
import time

import numpy as np

from ikaros.module import Module, Output, Parameter

_ONE = {"size": "1"}


class System(Module):
    """Publishes facts about the run every tick, for models that adapt to time or to load
    (and for plotting them in the web UI). The outputs are Ikaros 3's (today's interface),
    with this project's TICKS_PER_SECOND and CORES kept beside TICKS_PER_S and CPU_CORES
    (the same values). The reference gives their names, not their computation: what
    follows is this project's reading.

    TICK is the current tick (the first is 0 in an Ikaros 2 file, 1 in an Ikaros 3 file),
    NOMINAL_TIME ``tick * tick_duration`` in seconds, TIME the module time as Ikaros 3's
    kernel gives it (the real time in real-time mode, otherwise the nominal time),
    TICK_DURATION the model's ``tick_duration``, REAL_TIME the seconds since the run
    started, UPTIME the seconds since the network was built, LAG how many seconds late
    this tick started in real-time mode (0 in the other modes). STATE is the run mode as
    Ikaros 3 numbers it (1 stop, 2 pause, 3 play, 4 realtime, 5 fast forward; a tick
    stepped from pause is 2, a network stepped from Python is 3) and RUN_STATE the same
    as five flags, one per mode in that order. ACTUAL_DURATION is the wall time since the
    previous tick started, TICK_TIME_USAGE the time the last completed tick took to
    compute, TIME_USAGE that time as a fraction of tick_duration, IDLE_RATIO the rest of
    the tick (1 - TIME_USAGE, at least 0) and OVERLOAD 1 when the last tick took longer
    than tick_duration (these three are 0 with tick_duration 0). TICKS_PER_SECOND (and
    TICKS_PER_S) is the ticks per second of real time and CPU_USAGE the process's CPU time
    (user and system) per second of real time divided by CORES (0..1), both over the last
    ``window`` ticks (0 until there are two). STOP_AFTER_KNOWN is 1 when the model gives
    the number of ticks it runs (``stop``), and PROGRESS then the fraction of them done
    with this tick (else 0). CORES (and CPU_CORES) is the number of processor cores,
    MODULE_COUNT the number of modules of the network and CLASS_COUNT the number of
    different classes they belong to. Before the first tick (the value of tick -1) TICK
    is -1 and the rates are 0."""

    window = Parameter(100, "ticks over which TICKS_PER_SECOND and CPU_USAGE are measured",
                       type="int", range=(2, None), fixed=True)
    TICK = Output("the current tick", **_ONE)
    TIME = Output("the module time: the real time in real-time mode, otherwise the nominal "
                  "time", **_ONE)
    NOMINAL_TIME = Output("tick * tick_duration, in seconds", **_ONE)
    REAL_TIME = Output("seconds since the run started, at the start of this tick", **_ONE)
    UPTIME = Output("seconds since the network was built", **_ONE)
    RUN_STATE = Output("one flag per run mode: stop, pause, play, realtime, fast forward",
                       size="5")
    STATE = Output("the run mode: 1 stop, 2 pause, 3 play, 4 realtime, 5 fast forward",
                   **_ONE)
    TICK_DURATION = Output("the model's tick_duration in seconds", **_ONE)
    ACTUAL_DURATION = Output("seconds since the previous tick started", **_ONE)
    TICK_TIME_USAGE = Output("seconds the last completed tick took to compute", **_ONE)
    LAG = Output("seconds this tick started after its deadline in real-time mode; 0 in "
                 "the other modes", **_ONE)
    TICKS_PER_SECOND = Output("ticks per second of real time over the last window ticks",
                              **_ONE)
    TICKS_PER_S = Output("Ikaros 3's name of TICKS_PER_SECOND", alias="TICKS_PER_SECOND")
    CPU_USAGE = Output("the process's CPU time per second of real time, divided by CORES, "
                       "over the last window ticks", **_ONE)
    TIME_USAGE = Output("TICK_TIME_USAGE as a fraction of tick_duration", **_ONE)
    IDLE_RATIO = Output("the fraction of tick_duration not used: 1 - TIME_USAGE, at least 0",
                        **_ONE)
    OVERLOAD = Output("1 when the last tick took longer than tick_duration", **_ONE)
    PROGRESS = Output("the fraction of the model's stop ticks done (0 without stop)", **_ONE)
    STOP_AFTER_KNOWN = Output("1 when the model gives its number of ticks (stop)", **_ONE)
    CORES = Output("the number of processor cores", **_ONE)
    CPU_CORES = Output("Ikaros 3's name of CORES", alias="CORES")
    MODULE_COUNT = Output("the number of modules of the network", **_ONE)
    CLASS_COUNT = Output("the number of different classes of the network's modules", **_ONE)

    def init(self):
        self._cores = os.cpu_count() or 1
        # (wall-clock time, process CPU time) at each of the last window ticks
        self._samples = collections.deque(maxlen=self.window)
        self._previous = None       # wall time when the previous tick started
        self._publish()

    def tick(self):
        now = time.perf_counter()
        self.ACTUAL_DURATION[0] = now - self._previous if self._previous is not None else 0
        self._previous = now
        self._samples.append((now, time.process_time()))
        self._publish()

    def _publish(self):
        clock, run = self.clock, self.clock.run
        self.TICK[0] = clock.tick
        self.NOMINAL_TIME[0] = clock.time
        self.TICK_DURATION[0] = clock.tick_duration
        self.REAL_TIME[0] = clock.real_time
        self.LAG[0] = clock.lag
        self.CORES[0] = self._cores
        self._rates()
        if run is None:                 # no kernel facts (a module outside a network)
            self.TIME[0] = clock.time
            return
        mode = run.mode
        self.TIME[0] = clock.real_time if mode == 4 else clock.time
        self.UPTIME[0] = run.uptime
        self.STATE[0] = mode
        self.RUN_STATE[...] = np.arange(1, 6) == mode
        self.MODULE_COUNT[0] = run.module_count
        self.CLASS_COUNT[0] = run.class_count
        stop = run.stop_tick
        self.STOP_AFTER_KNOWN[0] = stop is not None
        self.PROGRESS[0] = min(1.0, (run.ticks_done + 1) / stop) if stop else 0.0
        used = run.tick_time_usage
        self.TICK_TIME_USAGE[0] = used
        duration = clock.tick_duration
        share = used / duration if duration > 0 else 0.0
        self.TIME_USAGE[0] = share
        self.IDLE_RATIO[0] = max(0.0, 1.0 - share) if duration > 0 else 0.0
        self.OVERLOAD[0] = duration > 0 and used > duration

    def _rates(self):
        samples = self._samples
        rate = usage = 0.0
        if len(samples) >= 2:
            (wall0, cpu0), (wall1, cpu1) = samples[0], samples[-1]
            if wall1 > wall0:
                rate = (len(samples) - 1) / (wall1 - wall0)
                usage = (cpu1 - cpu0) / ((wall1 - wall0) * self._cores)
        self.TICKS_PER_SECOND[0] = rate
        self.CPU_USAGE[0] = usage
