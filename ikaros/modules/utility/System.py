"""System: the kernel's clock and the run's speed as outputs a model can use."""
import collections
import os
import time

from ikaros.module import Module, Output, Parameter


class System(Module):
    """Publishes facts about the run every tick, for models that adapt to time or to load
    (and for plotting them in the web UI). TICK is the current tick (the first is 0), TIME
    the nominal time ``tick * tick_duration`` in seconds, TICK_DURATION the model's
    ``tick_duration``, REAL_TIME the seconds since the network was built, LAG how many
    seconds late this tick started in real-time mode (0 in the other modes),
    TICKS_PER_SECOND the ticks per second of real time and CPU_USAGE the process's CPU
    time (user and system) per second of real time divided by CORES (0..1), both over the
    last ``window`` ticks (0 until there are two), and CORES the number of processor cores.
    Before the first tick (the value of tick -1) TICK is -1 and the rates are 0. The class
    exists in Ikaros 3, whose reference does not describe its interface: these output
    names are this project's own, so an Ikaros 3 model that reads System's outputs may need
    its connections renamed."""

    window = Parameter(100, "ticks over which TICKS_PER_SECOND and CPU_USAGE are measured",
                       type="int", range=(2, None), fixed=True)
    TICK = Output("the current tick (the first is 0)", size="1")
    TIME = Output("the nominal time in seconds: tick * tick_duration", size="1")
    TICK_DURATION = Output("the model's tick_duration in seconds", size="1")
    REAL_TIME = Output("seconds since the network was built, at the start of this tick",
                       size="1")
    LAG = Output("seconds this tick started after its deadline in real-time mode; 0 in "
                 "the other modes", size="1")
    TICKS_PER_SECOND = Output("ticks per second of real time over the last window ticks",
                              size="1")
    CPU_USAGE = Output("the process's CPU time per second of real time, divided by CORES, "
                       "over the last window ticks", size="1")
    CORES = Output("the number of processor cores", size="1")

    def init(self):
        self._cores = os.cpu_count() or 1
        # (wall-clock time, process CPU time) at each of the last window ticks
        self._samples = collections.deque(maxlen=self.window)
        self._publish()

    def tick(self):
        self._samples.append((time.perf_counter(), time.process_time()))
        self._publish()

    def _publish(self):
        clock = self.clock
        self.TICK[0] = clock.tick
        self.TIME[0] = clock.time
        self.TICK_DURATION[0] = clock.tick_duration
        self.REAL_TIME[0] = clock.real_time
        self.LAG[0] = clock.lag
        self.CORES[0] = self._cores
        samples = self._samples
        rate = usage = 0.0
        if len(samples) >= 2:
            (wall0, cpu0), (wall1, cpu1) = samples[0], samples[-1]
            if wall1 > wall0:
                rate = (len(samples) - 1) / (wall1 - wall0)
                usage = (cpu1 - cpu0) / ((wall1 - wall0) * self._cores)
        self.TICKS_PER_SECOND[0] = rate
        self.CPU_USAGE[0] = usage
