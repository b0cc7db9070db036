"""SpikeGenerator: a population of poisson, regular or triggered spike sources (Ikaros 3)."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class SpikeGenerator(Module):
    """Generates spikes, one generator per element. ``regular``: each generator's PHASE
    (in cycles, starting at ``initial_phase``) grows by rate·tick_duration every tick, in
    float32; when it reaches 1 the generator spikes once per whole cycle and keeps the
    fraction. ``poisson``: a generator spikes with probability rate·tick_duration per tick
    (at most once; not within ``refractory_period`` seconds of its last spike), drawn from
    NumPy's generator seeded with ``seed`` (a negative seed: a different run every time);
    its PHASE stays 0. ``triggered``: a generator spikes on a tick when TRIGGER is above 0
    (``level``) or has just become so (``rising_edge``: it was 0 or below on the previous
    tick); its PHASE stays 0. The rate is RATE (spikes/s, per element) when connected, else
    ``firing_rate``; negative rates count as 0. Where ENABLE is connected and 0 or below a
    generator does not spike (its phase still runs). RESET above 0 restarts a generator
    (phase, trigger memory, refractory time). SPIKE_COUNT is the spikes of the tick,
    SPIKES 1 where it is above 0, FIRING_RATE the count divided by tick_duration and
    EFFECTIVE_RATE the rate used. The regular and triggered modes were checked against the
    original's outputs; the reference does not describe the poisson mode's random draws, so
    its spike trains differ from the original's run for run. New in Ikaros 3."""

    population_size = Parameter(1, "the number of generators", type="int", range=(1, None))
    mode = Parameter("poisson", "random, clock-like or input-driven spikes",
                     options="poisson/regular/triggered")
    firing_rate = Parameter(10.0, "spikes per second when RATE is not connected")
    initial_phase = Parameter(0.0, "the starting phase of regular generators, in cycles")
    refractory_period = Parameter(0.0, "the least interval between spikes in poisson mode (s)")
    trigger_mode = Parameter("rising_edge", "when TRIGGER gives a spike",
                             options="rising_edge/level")
    seed = Parameter(-1, "the random seed of poisson mode; negative: a different run every "
                     "time", type="int")
    RATE = Input("the rate of each generator (spikes/s)", optional=True,
                 size="@population_size")
    TRIGGER = Input("triggered mode: above 0 gives a spike", optional=True,
                    size="@population_size")
    ENABLE = Input("0 or below keeps a generator silent", optional=True,
                   size="@population_size")
    RESET = Input("above 0 restarts a generator", optional=True, size="@population_size")
    SPIKES = Output("1 where a generator spiked this tick", shape="@population_size")
    SPIKE_COUNT = Output("the number of spikes of this tick", shape="@population_size")
    FIRING_RATE = Output("the spikes of this tick per second", shape="@population_size")
    EFFECTIVE_RATE = Output("the rate used (spikes/s)", shape="@population_size")
    PHASE = Output("the phase of regular generators, in cycles", shape="@population_size")

    def init(self):
        n = self.population_size
        self._rng = np.random.default_rng(None if self.seed < 0 else self.seed)
        self._previous = np.zeros(n, np.float32)
        self._since = np.full(n, np.inf)
        self.PHASE[...] = self.initial_phase if self.mode == "regular" else 0

    def _restart(self, where):
        self.PHASE[where] = self.initial_phase if self.mode == "regular" else 0
        self._previous[where] = 0
        self._since[where] = np.inf

    def tick(self):
        dt = self.clock.tick_duration
        if self.RESET is not None:
            self._restart(self.RESET > 0)
        rate = self.RATE if self.RATE is not None else np.full(self.population_size,
                                                               self.firing_rate, np.float32)
        rate = np.maximum(rate, 0).astype(np.float32)
        self.EFFECTIVE_RATE[...] = rate
        count = self.SPIKE_COUNT
        if self.mode == "regular":
            self.PHASE += rate * np.float32(dt)
            np.floor(self.PHASE, out=count)
            self.PHASE -= count
        elif self.mode == "triggered":
            trigger = self.TRIGGER if self.TRIGGER is not None else np.zeros_like(rate)
            fired = trigger > 0
            if self.trigger_mode == "rising_edge":
                fired &= self._previous <= 0
            self._previous[...] = trigger
            count[...] = fired
        else:
            self._since += dt
            fired = (self._rng.random(rate.size) < rate * dt) & \
                (self._since >= self.refractory_period)
            self._since[fired] = 0
            count[...] = fired
        if self.ENABLE is not None:
            count[self.ENABLE <= 0] = 0
        np.greater(count, 0, out=self.SPIKES, casting="unsafe")
        np.divide(count, np.float32(dt), out=self.FIRING_RATE)
