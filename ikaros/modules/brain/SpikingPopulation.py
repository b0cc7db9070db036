"""SpikingPopulation: a population of Izhikevich spiking neurons."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

# Izhikevich (2003) parameters (a, b, c, d) of the neuron types.
NEURON_TYPES = {
    "regular_spiking": (0.02, 0.2, -65.0, 8.0),
    "intrinsically_bursting": (0.02, 0.2, -55.0, 4.0),
    "chattering": (0.02, 0.2, -50.0, 2.0),
    "fast_spiking": (0.1, 0.2, -65.0, 2.0),
    "low_threshold": (0.02, 0.25, -65.0, 2.0),
    "resonator": (0.1, 0.26, -65.0, 2.0),
}
REST = -65.0


class SpikingPopulation(Module):
    """A population of ``population_size`` Izhikevich (2003) neurons of one type (a, b, c, d
    from the paper: regular_spiking 0.02, 0.2, -65, 8; intrinsically_bursting 0.02, 0.2, -55,
    4; chattering 0.02, 0.2, -50, 2; fast_spiking 0.1, 0.2, -65, 2; low_threshold 0.02, 0.25,
    -65, 2; resonator 0.1, 0.26, -65, 2). A tick is 1 ms. v starts at -65 and u at b*v. Each
    tick a neuron that spiked on the previous tick is reset (v = c, u += d); then v is
    integrated in ``substeps`` Euler steps of 1/substeps ms, v += (0.04 v^2 + 5 v + 140 - u +
    I) / substeps, with v held at ``threshold`` once it reaches it, and finally u += a (b v -
    u). OUTPUT is the membrane potential v, which equals ``threshold`` on the tick of a spike.
    The current I of neuron i is DIRECT_IN[i] (neurons past the end of DIRECT_IN get none)
    plus the synaptic input: every element of EXCITATION_IN at or above ``threshold`` (a
    spike, for example from another population's OUTPUT) adds its value times a weight, and
    every such element of INHIBITION_IN subtracts its value times a weight; the weights are
    drawn uniformly from synapse_min..synapse_max, one per neuron and input element, with
    ``seed``. ADENOSINE is adenosine_factor times the number of neurons spiking this tick.
    Ikaros 2 gave resonators c = +65 and low-threshold neurons a = 0.1 and let v run past
    the threshold within a tick; these are corrected here."""

    model_type = Parameter("Izhikevich", "the spiking neuron model", options="Izhikevich")
    neuron_type = Parameter("regular_spiking", "the Izhikevich neuron type",
                            options=list(NEURON_TYPES))
    population_size = Parameter(50, "number of neurons", type="int", range=(1, None))
    substeps = Parameter(2, "Euler steps per tick (1 ms) for the membrane potential",
                         type="int")
    threshold = Parameter(30.0, "spike threshold (mV): v is reset once it reaches this, and "
                          "input elements at or above it count as spikes")
    adenosine_factor = Parameter(1.0, "adenosine produced per spike")
    debug = Parameter(False, "print the number of spikes every tick")
    synapse_max = Parameter(1.5, "largest random synaptic weight")
    synapse_min = Parameter(0.5, "smallest random synaptic weight")
    seed = Parameter(None, "seed of the synaptic weights; unset (or 0) gives different "
                     "weights every run", type="int")
    DIRECT_IN = Input("direct input current of the neurons, one element per neuron (at most "
                      "population_size elements)", optional=True, flatten=True)
    EXCITATION_IN = Input("excitatory synaptic input: elements at or above threshold are "
                          "spikes", optional=True, flatten=True)
    INHIBITION_IN = Input("inhibitory synaptic input: elements at or above threshold are "
                          "spikes", optional=True, flatten=True)
    OUTPUT = Output("the membrane potentials (mV); threshold marks a spike",
                    size_param="population_size")
    ADENOSINE = Output("adenosine_factor times the number of spikes this tick", size="1")

    def init(self):
        n = self.population_size
        if n < 1:
            self.fatal_error("population_size must be at least 1")
            return
        a, b, c, d = NEURON_TYPES[self.neuron_type]
        self._abcd = (a, b, c, d)
        self._v = np.full(n, REST)
        self._u = b * self._v
        self._current = np.zeros(n)
        if self.DIRECT_IN is not None and self.DIRECT_IN.size > n:
            self.fatal_error(f"DIRECT_IN has {self.DIRECT_IN.size} elements but the "
                             f"population only {n} neurons")
        rng = np.random.default_rng(self.seed or None)
        lo, hi = sorted((self.synapse_min, self.synapse_max))
        self._w_exc = None if self.EXCITATION_IN is None else rng.uniform(
            lo, hi, (n, self.EXCITATION_IN.size))
        self._w_inh = None if self.INHIBITION_IN is None else rng.uniform(
            lo, hi, (n, self.INHIBITION_IN.size))
        self.OUTPUT[...] = self._v
        self.ADENOSINE[...] = 0

    def _spikes(self, x):
        x = x.astype(np.float64)
        return np.where(x >= self.threshold, x, 0.0)

    def tick(self):
        a, b, c, d = self._abcd
        v, u, th = self._v, self._u, self.threshold
        current = self._current
        current.fill(0.0)
        if self.DIRECT_IN is not None:
            m = min(self.DIRECT_IN.size, current.size)
            current[:m] = self.DIRECT_IN[:m]
        if self._w_exc is not None:
            current += self._w_exc @ self._spikes(self.EXCITATION_IN)
        if self._w_inh is not None:
            current -= self._w_inh @ self._spikes(self.INHIBITION_IN)

        fired = v >= th                      # spiked on the previous tick
        v[fired] = c
        u[fired] += d
        steps = max(1, self.substeps)
        dt = 1.0 / steps
        for _ in range(steps):
            v += dt * (0.04 * v * v + 5.0 * v + 140.0 - u + current)
            np.minimum(v, th, out=v)
        u += a * (b * v - u)

        self.OUTPUT[...] = v
        spikes = int(np.count_nonzero(v >= th))
        self.ADENOSINE[...] = self.adenosine_factor * spikes
        if self.debug:
            self.print(f"{spikes} spikes")
