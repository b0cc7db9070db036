"""SpikingPopulation: a population of Izhikevich spiking neurons."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter
from ikaros.modules.io._files import resolve
from ikaros.modules.neural import _connectivity as connectivity
from ikaros.modules.neural._spike_kernels import kernels
from ikaros.modules.neural._stdp import STDP

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
    -65, 2; resonator 0.1, 0.26, -65, 2). A tick advances the model by ``time_step`` ms (1 by
    default; 0 takes the kernel's tick_duration, in ms). v starts at -65 and u at b*v. Each
    tick a neuron that spiked on the previous tick is reset (v = c, u += d); then v is
    integrated in ``substeps`` Euler steps of h = time_step/substeps ms, v += h (0.04 v^2 +
    5 v + 140 - u + I), with v held at ``threshold`` once it reaches it, and finally u +=
    time_step a (b v - u). OUTPUT is the membrane potential v, which equals ``threshold`` on
    the tick of a spike. The current I of neuron i is DIRECT_IN[i] (neurons past the end of
    DIRECT_IN get none) plus the synaptic input: every element j of EXCITATION_IN at or above
    ``threshold`` is a spike and adds W_exc[i, j] times its value (``spike_input`` value, as
    before issue 30) or W_exc[i, j] alone (``spike_input`` flag); INHIBITION_IN subtracts in
    the same way through W_inh. Only the columns of the elements that spiked are read, so a
    tick costs in proportion to the spikes. The weights (float32, receivers x input
    elements) come from, in this order: a matrix parameter (``excitation_weights``,
    ``inhibition_weights``; zeros are no synapse), a file (``*_weights_file``: .npy, a .npz
    of scipy.sparse.save_npz or of numpy.savez with row, col, data and shape, or .csv/.txt),
    or are drawn with ``seed``: each pair is a synapse with ``excitation_probability`` (or
    ``inhibition_probability``), its weight uniform in synapse_min..synapse_max (inhibition:
    in inhibition_synapse_range when it is set). With probability 1 (the default) the weights are
    those the seed gave before connectivity became data. With ``stdp`` the excitatory
    synapses learn by pair-based STDP with traces: every tick the sender traces x decay by
    exp(-time_step/stdp_tau_plus) and the receiver traces y by exp(-time_step/stdp_tau_minus);
    a spike of sender j adds 1 to x_j after lowering each of its weights w_ij by stdp_a_minus
    * y_i; a spike of neuron i adds 1 to y_i and raises each weight w_ij onto it by
    stdp_a_plus * x_j (so a sender spike arriving on the same tick counts as before); weights
    stay in 0..stdp_w_max. EXCITATION_WEIGHTS shows W_exc when ``weights_output`` is set.
    ADENOSINE is adenosine_factor times the number of neurons spiking this tick.

    Ikaros 3's inputs (this project's reading of its interface; no run of the original was
    compared): EXCITATION and INHIBITION are EXCITATION_IN and INHIBITION_IN under Ikaros
    3's names (connect one name of each). EXCITATION_TOPOLOGY, when connected, gives the
    excitatory weights instead (a matrix, a row per neuron and a column per element of
    EXCITATION, read every tick: zero is no synapse; STDP does not learn it).
    INTERNAL_TOPOLOGY (population_size × population_size, row the receiving neuron, column
    the sender) connects the population to itself: a neuron that spiked on the previous
    tick sends each neuron its weight times its spike, as an input spike of EXCITATION
    does (a negative weight inhibits). ``debugmode`` is Ikaros 3's name of ``debug``. This
    project's earlier reading of the Ikaros 2 code (not checked against the original: its
    golden files have no SpikingPopulation case, its outputs being random) is that it gave
    resonators c = +65 and low-threshold neurons a = 0.1 and let v run past the threshold
    within a tick; this class uses the paper's values instead. The reference says only that the
    neurons are driven through random weights in synapse_min..synapse_max and integrated in
    substeps per tick: it does not say how long a tick is or whether a spike counts by its
    value, so the 1 ms tick and the value times the weight of this class's first version stay
    the defaults."""

    model_type = Parameter("Izhikevich", "the spiking neuron model", options="Izhikevich")
    neuron_type = Parameter("regular_spiking", "the Izhikevich neuron type",
                            options=list(NEURON_TYPES))
    population_size = Parameter(50, "number of neurons", type="int", range=(1, None),
                                default_v3=1)
    substeps = Parameter(2, "Euler steps per tick for the membrane potential", type="int")
    time_step = Parameter(1.0, "model time (ms) of one tick; 0: the kernel's tick_duration",
                          range=(0, None))
    threshold = Parameter(30.0, "spike threshold (mV): v is reset once it reaches this, and "
                          "input elements at or above it count as spikes")
    spike_input = Parameter("value", "what an input spike adds: its value times the weight, "
                            "or the weight alone (flag)", options="value,flag")
    adenosine_factor = Parameter(1.0, "adenosine produced per spike")
    debug = Parameter(False, "print the number of spikes every tick")
    debugmode = Parameter(False, "Ikaros 3's name of debug")
    synapse_max = Parameter(1.5, "largest random synaptic weight")
    synapse_min = Parameter(0.5, "smallest random synaptic weight")
    inhibition_synapse_range = Parameter(None, "smallest and largest random inhibitory "
                                         "weight; empty: synapse_min synapse_max",
                                         type="array", fixed=True)
    excitation_probability = Parameter(1.0, "probability that a neuron has a synapse from "
                                       "an element of EXCITATION_IN", range=(0, 1),
                                       fixed=True)
    inhibition_probability = Parameter(1.0, "probability that a neuron has a synapse from "
                                       "an element of INHIBITION_IN", range=(0, 1),
                                       fixed=True)
    excitation_weights = Parameter(None, "excitatory weights (neurons x EXCITATION_IN "
                                   "elements); empty: from the file or drawn", type="matrix",
                                   fixed=True)
    inhibition_weights = Parameter(None, "inhibitory weights (neurons x INHIBITION_IN "
                                   "elements); empty: from the file or drawn", type="matrix",
                                   fixed=True)
    excitation_weights_file = Parameter("", "file of the excitatory weights (.npy, .npz, "
                                        ".csv, .txt)", file=True, fixed=True)
    inhibition_weights_file = Parameter("", "file of the inhibitory weights (.npy, .npz, "
                                        ".csv, .txt)", file=True, fixed=True)
    synapse_storage = Parameter("auto", "how the weights are kept: dense, by sender "
                                "(sparse), or auto: dense when more than a quarter of the "
                                "pairs are synapses", options="auto,dense,sparse", fixed=True)
    spike_kernel = Parameter("auto", "auto: the neurons and the spikes they receive are "
                             "computed by loops compiled with numba when it is installed "
                             "(ikaros[fast]); numpy: by NumPy (the same numbers)",
                             options="auto,numpy", fixed=True)
    seed = Parameter(None, "seed of the synaptic weights; unset (or 0) gives different "
                     "weights every run", type="int")
    stdp = Parameter(False, "the excitatory synapses learn by STDP", fixed=True)
    stdp_a_plus = Parameter(0.01, "potentiation per pre-before-post pair", range=(0, None))
    stdp_a_minus = Parameter(0.012, "depression per post-before-pre pair", range=(0, None))
    stdp_tau_plus = Parameter(20.0, "time constant (ms) of the sender traces",
                              range=(0, None))
    stdp_tau_minus = Parameter(20.0, "time constant (ms) of the receiver traces",
                               range=(0, None))
    stdp_w_max = Parameter(1.5, "largest weight STDP can reach", range=(0, None))
    weights_output = Parameter(False, "show the excitatory weights on EXCITATION_WEIGHTS",
                               fixed=True)
    DIRECT_IN = Input("direct input current of the neurons, one element per neuron (at most "
                      "population_size elements)", optional=True, flatten=True)
    EXCITATION_IN = Input("excitatory synaptic input: elements at or above threshold are "
                          "spikes", optional=True, flatten=True)
    INHIBITION_IN = Input("inhibitory synaptic input: elements at or above threshold are "
                          "spikes", optional=True, flatten=True)
    EXCITATION = Input("Ikaros 3's name of EXCITATION_IN", optional=True, flatten=True)
    INHIBITION = Input("Ikaros 3's name of INHIBITION_IN", optional=True, flatten=True)
    EXCITATION_TOPOLOGY = Input("the excitatory weights, neurons x EXCITATION elements, read "
                                "every tick (instead of the drawn or given ones)",
                                optional=True)
    INTERNAL_TOPOLOGY = Input("weights among the neurons, receiver x sender: the previous "
                              "tick's spikes feed back through them", optional=True)
    OUTPUT = Output("the membrane potentials (mV); threshold marks a spike",
                    size_param="population_size")
    ADENOSINE = Output("adenosine_factor times the number of spikes this tick", size="1")
    EXCITATION_WEIGHTS = Output("the excitatory weights (neurons x EXCITATION_IN elements) "
                                "when weights_output is set, else empty")

    def _input(self, name):
        """The input under its Ikaros 2 name (``EXCITATION_IN``) or its Ikaros 3 one."""
        v2, v3 = getattr(self, name + "_IN", None), getattr(self, name, None)
        return v2 if v2 is not None else v3

    def set_sizes(self):
        shape = self.input_shape("EXCITATION_IN") or self.input_shape("EXCITATION")
        if self.weights_output and shape is not None:
            self.set_output_shape("EXCITATION_WEIGHTS",
                                  (self.population_size, int(np.prod(shape))))
        else:
            self.set_output_shape("EXCITATION_WEIGHTS", (0,))

    def init(self):
        n = self.population_size
        a, b, c, d = NEURON_TYPES[self.neuron_type]
        self._abcd = (a, b, c, d)
        self._v = np.full(n, REST)
        self._u = b * self._v
        self._current = np.zeros(n)
        self._synaptic_current = np.zeros(n)
        self._kernels = kernels() if self.spike_kernel == "auto" else None
        self._compiled = self._kernels is not None
        self._spiking_buffer = np.zeros(n, dtype=np.int64)
        if self.DIRECT_IN is not None and self.DIRECT_IN.size > n:
            raise ValueError(f"DIRECT_IN has {self.DIRECT_IN.size} elements but the "
                             f"population only {n} neurons")
        for name in ("EXCITATION", "INHIBITION"):
            if getattr(self, name) is not None and getattr(self, name + "_IN") is not None:
                raise ValueError(f"connect {name}_IN (Ikaros 2) or {name} (Ikaros 3), not "
                                 f"both")
        self._excitation, self._inhibition = self._input("EXCITATION"), \
            self._input("INHIBITION")
        self._check_topologies(n)
        rng = np.random.default_rng(self.seed or None)
        self._exc = None if self.EXCITATION_TOPOLOGY is not None else self._projection(
            rng, "excitation", self._excitation, (self.synapse_min, self.synapse_max))
        inh_range = np.ravel(self.inhibition_synapse_range)
        if inh_range.size not in (0, 2):
            raise ValueError(f"inhibition_synapse_range has {inh_range.size} values; it "
                             f"needs two (smallest and largest weight) or none")
        self._inh = self._projection(rng, "inhibition", self._inhibition,
                                     inh_range if inh_range.size else
                                     (self.synapse_min, self.synapse_max))
        self._stdp = None
        if self.stdp and self._exc is not None:
            self._exc = self._exc.as_sparse()
            self._stdp = STDP(self._exc, self.stdp_a_plus, self.stdp_a_minus,
                              self.stdp_tau_plus, self.stdp_tau_minus, self.stdp_w_max)
        self._show_weights()
        self.OUTPUT[...] = self._v
        self.ADENOSINE[...] = 0

    def _check_topologies(self, n):
        excitation = self._excitation
        for name, shape in (("INTERNAL_TOPOLOGY", (n, n)), ("EXCITATION_TOPOLOGY", (
                n, 0 if excitation is None else excitation.size))):
            x = getattr(self, name)
            if x is not None and x.shape != shape:
                raise ValueError(f"{name} has shape {x.shape}; it must be {shape} (a row per "
                                 f"neuron, a column per sender)")
        if self.EXCITATION_TOPOLOGY is not None and self.stdp:
            raise ValueError("stdp learns drawn or given weights, not EXCITATION_TOPOLOGY's")

    def _topology_current(self, current, weights, senders, values):
        """current += weights[:, senders] @ values (or the sum of the columns)."""
        if senders.size:
            columns = weights[:, senders].astype(np.float64)
            current += columns @ values if values is not None else columns.sum(axis=1)

    def _projection(self, rng, kind, x, weight_range):
        """The weights of one input: the matrix parameter, the file, or drawn."""
        if x is None:
            return None
        shape = (self.population_size, x.size)
        matrix = getattr(self, f"{kind}_weights")
        filename = getattr(self, f"{kind}_weights_file")
        if matrix is not None and np.size(matrix):
            p = connectivity.from_matrix(matrix, shape, f"{kind}_weights")
        elif filename:
            p = connectivity.load(resolve(self, filename), shape, f"{kind}_weights_file")
        else:
            lo, hi = sorted(weight_range)
            p = connectivity.random(rng, shape, lo, hi, getattr(self, f"{kind}_probability"))
        if self.synapse_storage == "sparse":
            return p.as_sparse()
        return p.as_dense() if self.synapse_storage == "dense" else p

    def _show_weights(self):
        if self.EXCITATION_WEIGHTS.size:
            self.EXCITATION_WEIGHTS[...] = self._exc.to_dense()

    def _spiking(self, x):
        """The elements of an input that spiked, and their values (None for flags)."""
        senders = np.flatnonzero(x >= self.threshold)
        return senders, (x[senders] if self.spike_input == "value" else None)

    def _synaptic(self, projection, senders, values):
        """The current the spikes of one input bring, summed from 0 in float64."""
        total = self._synaptic_current
        total.fill(0.0)
        projection.add_spikes(total, senders, values, self._compiled)
        return total

    def tick(self):
        a, b, c, d = self._abcd
        v, u, th = self._v, self._u, self.threshold
        current = self._current
        current.fill(0.0)
        if self.DIRECT_IN is not None:
            m = min(self.DIRECT_IN.size, current.size)
            current[:m] = self.DIRECT_IN[:m]
        dt = self.time_step or 1000.0 * self.clock.tick_duration
        pre = None
        if self._exc is not None:
            pre, values = self._spiking(self._excitation)
            current += self._synaptic(self._exc, pre, values)
        elif self.EXCITATION_TOPOLOGY is not None and self._excitation is not None:
            self._topology_current(current, self.EXCITATION_TOPOLOGY,
                                   *self._spiking(self._excitation))
        if self.INTERNAL_TOPOLOGY is not None:
            self._topology_current(current, self.INTERNAL_TOPOLOGY,
                                   *self._spiking(self.OUTPUT.reshape(-1)))
        if self._inh is not None:
            current -= self._synaptic(self._inh, *self._spiking(self._inhibition))

        steps = max(1, self.substeps)
        if self._compiled:
            count = self._kernels.izhikevich(v, u, current, a, b, c, d, th, steps, dt / steps,
                                             dt * a, self.OUTPUT.reshape(-1),
                                             self._spiking_buffer)
            spiking = self._spiking_buffer[:count]
        else:
            fired = v >= th                      # spiked on the previous tick
            v[fired] = c
            u[fired] += d
            h = dt / steps
            for _ in range(steps):
                v += h * (0.04 * v * v + 5.0 * v + 140.0 - u + current)
                np.minimum(v, th, out=v)
            u += (dt * a) * (b * v - u)
            self.OUTPUT[...] = v
            spiking = np.flatnonzero(v >= th)
        if self._stdp is not None:
            self._stdp.decay(dt)
            self._stdp.on_pre(pre)
            self._stdp.on_post(spiking)
            self._show_weights()
        self.ADENOSINE[...] = self.adenosine_factor * spiking.size
        if self.debug or self.debugmode:
            self.print(f"{spiking.size} spikes")
