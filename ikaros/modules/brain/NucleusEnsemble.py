"""NucleusEnsemble: a population of nuclei with topologies and neuromodulation."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter, require
from ikaros.modules.io._files import resolve
from ikaros.modules.neural import _connectivity as connectivity

from ._nucleus import ATAN_1, TAN_1

NA_THRESHOLD = 0.5          # noradrenaline threshold when NA_THRESHOLD is not connected
WEIGHT_MIN, WEIGHT_MAX = 0.01, 100.0
SPARSE_FROM = 1 << 18       # synapse_storage auto: sparse from this many pairs (when sparse)
INPUTS = (("EXCITATION", "excitation", "EX_TOPOLOGY"),
          ("INHIBITION", "inhibition", "INH_TOPOLOGY"),
          ("SHUNTING_INHIBITION", "shunting_inhibition", "SH_INH_TOPOLOGY"))


def _activation(name, x, divisor):
    x = np.maximum(x, 0.0)
    if name == "relu":
        return x
    if name == "secondorder":
        return 2 * x * x / (1 + x * x)
    return np.arctan(x) / divisor            # scaledsigmoid


class NucleusEnsemble(Module):
    """A population of ``size`` nuclei. Each input reaches the nuclei through a topology
    matrix (rows: nuclei, columns: input elements): one_to_one (input i drives nucleus i),
    all_to_all, lateral (nucleus i is inhibited by inputs i-1 and i+1, wrapping around) or
    wta (each nucleus is inhibited by the inputs of all the others); a single nucleus takes
    all elements of every input. EX_TOPOLOGY,
    INH_TOPOLOGY and SH_INH_TOPOLOGY replace them when connected. With ``scale`` each
    weighted sum is divided by the number of inputs connected to that nucleus. The drive of
    nucleus i is a = phi * w_i * E_i / (1 + psi * S_i) - chi * I_i + tau * R_i +/- NA_i,
    where R is the nucleus's own previous output when ``recurrent_topology`` is excitatory
    (+) or inhibitory (-), and noradrenaline NA is added when it is at least NA_THRESHOLD
    (0.5 when unconnected) and subtracted below. The state follows x += epsilon * (a - x);
    a tetanus trace follows T = (1 - tetanus_leak) * T + tetanus_factor * a. A nucleus whose
    T reaches its THRESHOLD = max(0, threshold + rho * ADENO_INPUT - sigma * DOPAMINE) outputs
    alpha + beta * f(x), otherwise alpha; f is relu, scaledsigmoid (atan(x) divided by
    ``sigmoid_divisor``: tan(1) as in Ikaros 2, whose Nucleus the golden files show dividing
    so, or atan(1), which makes f(1) = 1) or secondorder (2x^2/(1+x^2)), all 0 for x < 0. ADENO_OUTPUT equals OUTPUT. When SETPOINT is
    connected the excitation weights w (initially 1) adapt: for an active nucleus its output
    enters a window of the last ``moving_avg_window_size`` values (initially 1) and w +=
    ADAPTATIONRATE (0.001 when unconnected) * (SETPOINT - window mean), kept in 0.01..100.
    Modulatory inputs have one element per nucleus or one shared element. Besides the named
    topologies, a topology can be ``random`` (each nucleus-input pair connected with
    ``connection_probability``, weight 1, drawn with ``seed``) or be read from a file
    (``*_weights_file``: .npy, .npz of scipy.sparse.save_npz or of numpy.savez with row,
    col, data and shape, .csv, .txt; nuclei x input elements, float32), which replaces the
    topology parameter. With ``synapse_storage`` auto a topology of at least 262,144 pairs of
    which at most a quarter are connected is kept sparse and multiplied with scipy.sparse
    (the extra ikaros[scipy]); ``sparse`` asks for that always, ``dense`` never. This
    project's earlier reading of the original's code (not checked against the original:
    the golden file of Ikaros 2 has only a case without inputs) is that Ikaros 2 left the
    lateral topologies empty, averaged the window over ``size`` values and replaced phi by
    w; this class does not copy those. Ikaros 3 has no NucleusEnsemble."""

    debug = Parameter(False, "print the state of the ensemble every tick")
    size = Parameter(1, "number of nuclei", type="int", range=(1, None))
    alpha = Parameter(0.0, "output offset (the output of an inactive nucleus)")
    beta = Parameter(1.0, "output gain")
    phi = Parameter(1.0, "weight of the excitation")
    chi = Parameter(1.0, "weight of the inhibition")
    psi = Parameter(1.0, "weight of the shunting inhibition")
    tau = Parameter(1.0, "weight of the recurrent connection")
    scale = Parameter(True, "divide each weighted input sum by the number of inputs connected "
                      "to the nucleus")
    epsilon = Parameter(0.1, "rate (0..1) at which the state approaches the drive", range=(0, 1))
    sigma = Parameter(1.0, "weight of DOPAMINE, which lowers the threshold")
    rho = Parameter(1.0, "weight of ADENO_INPUT, which raises the threshold")
    threshold = Parameter(0.0, "the tetanus needed for a nucleus to be active")
    tetanus_factor = Parameter(1.0, "how much the drive adds to the tetanus trace")
    tetanus_leak = Parameter(1.0, "fraction of the tetanus trace lost each tick (1: the trace "
                             "is the current drive)", range=(0, 1))
    excitation_topology = Parameter("one_to_one", "how EXCITATION reaches the nuclei",
                                    options="one_to_one/all_to_all/random")
    inhibition_topology = Parameter("one_to_one", "how INHIBITION reaches the nuclei",
                                    options="one_to_one/lateral/wta/random")
    shunting_inhibition_topology = Parameter("one_to_one", "how SHUNTING_INHIBITION reaches "
                                             "the nuclei", options="one_to_one/lateral/wta/"
                                             "random")
    connection_probability = Parameter(0.1, "probability of each nucleus-input pair of a "
                                       "random topology", range=(0, 1))
    seed = Parameter(None, "seed of the random topologies; unset (or 0) gives different ones "
                     "every run", type="int")
    excitation_weights_file = Parameter("", "file of the excitation weights (nuclei x "
                                        "EXCITATION elements), replacing "
                                        "excitation_topology", file=True, fixed=True)
    inhibition_weights_file = Parameter("", "file of the inhibition weights, replacing "
                                        "inhibition_topology", file=True, fixed=True)
    shunting_inhibition_weights_file = Parameter("", "file of the shunting inhibition "
                                                 "weights, replacing "
                                                 "shunting_inhibition_topology", file=True,
                                                 fixed=True)
    synapse_storage = Parameter("auto", "how the topologies are kept: dense, sparse "
                                "(scipy.sparse products), or auto: sparse when large and at "
                                "most a quarter connected", options="auto,dense,sparse",
                                fixed=True)
    recurrent_topology = Parameter("none", "each nucleus's connection to its own previous "
                                   "output", options="none/excitatory/inhibitory")
    activation_function = Parameter("scaledsigmoid", "the output function f",
                                    options="relu/scaledsigmoid/secondorder")
    sigmoid_divisor = Parameter("tan1", "scaledsigmoid is atan(x) / tan(1) (Ikaros 2) or / "
                                "atan(1) (f(1) = 1)", options="tan1/atan1")
    moving_avg_window_size = Parameter(100, "length of the output window used to adapt to "
                                       "SETPOINT", type="int")

    EXCITATION = Input("excitatory input", optional=True, flatten=True)
    INHIBITION = Input("subtractive inhibitory input", optional=True, flatten=True)
    SHUNTING_INHIBITION = Input("shunting inhibitory input", optional=True, flatten=True)
    DOPAMINE = Input("lowers the threshold (weighted by sigma)", optional=True, flatten=True)
    NORADRENALINE = Input("added to the drive when at least NA_THRESHOLD, else subtracted",
                          optional=True, flatten=True)
    NA_THRESHOLD = Input("the noradrenaline threshold (0.5 when unconnected)", optional=True,
                         flatten=True)
    ADENO_INPUT = Input("raises the threshold (weighted by rho)", optional=True, flatten=True)
    SETPOINT = Input("the output level the excitation weights adapt towards", optional=True,
                     flatten=True)
    ADAPTATIONRATE = Input("the rate of the adaptation to SETPOINT (0.001 when unconnected)",
                           optional=True, flatten=True)
    EX_TOPOLOGY = Input("a matrix (nuclei x excitation elements) replacing "
                        "excitation_topology", optional=True)
    INH_TOPOLOGY = Input("a matrix (nuclei x inhibition elements) replacing "
                         "inhibition_topology", optional=True)
    SH_INH_TOPOLOGY = Input("a matrix (nuclei x shunting elements) replacing "
                            "shunting_inhibition_topology", optional=True)

    OUTPUT = Output("the output of the nuclei", size_param="size")
    ADENO_OUTPUT = Output("adenosine produced: a copy of OUTPUT", size_param="size")
    THRESHOLD = Output("the current thresholds", size_param="size")
    TETANUS = Output("the tetanus traces", size_param="size")

    # --- set-up ---------------------------------------------------------------------------
    def _topology(self, kind, n_in):
        n = self.size
        if kind == "all_to_all" or n == 1:
            return np.ones((n, n_in))
        rows = np.arange(n)[:, None]
        cols = np.arange(n_in)[None, :]
        if kind == "lateral":
            return ((cols == (rows - 1) % n_in) | (cols == (rows + 1) % n_in)).astype(float)
        if kind == "wta":
            return (cols != rows % n_in).astype(float) if n_in == n else np.ones((n, n_in))
        return (cols == rows).astype(float)                  # one_to_one

    def _vector(self, x, default):
        """A modulatory input as one value per nucleus (None when unconnected)."""
        if x is None:
            return None if default is None else np.full(self.size, default)
        if x.size in (1, self.size):
            return np.broadcast_to(x.astype(np.float64), (self.size,))
        self.fatal_error(f"a modulatory input has {x.size} elements; it needs 1 or {self.size}")
        return np.zeros(self.size)

    def _projection(self, rng, kind, n_in):
        """The fixed topology of one input: from its file, drawn, or named."""
        shape = (self.size, n_in)
        filename = getattr(self, f"{kind}_weights_file")
        if filename:
            p = connectivity.load(resolve(self, filename), shape, f"{kind}_weights_file")
        elif getattr(self, f"{kind}_topology") == "random":
            p = connectivity.random(rng, shape, 1.0, 1.0, self.connection_probability)
        else:
            p = connectivity.from_matrix(self._topology(getattr(self, f"{kind}_topology"),
                                                        n_in), shape)
        sparse = self.synapse_storage == "sparse" or (
            self.synapse_storage == "auto" and n_in * self.size >= SPARSE_FROM
            and p.synapse_count <= connectivity.DENSE_ABOVE * n_in * self.size)
        if not sparse:
            return p.as_dense()
        if self._sparse is None:
            self._sparse = require("scipy.sparse", "scipy", extra="scipy")
        return p.as_sparse()

    @staticmethod
    def _row_counts(p):
        """The number of synapses onto each nucleus."""
        if p.is_dense:
            return np.count_nonzero(p.dense, axis=1)
        return np.bincount(p.indices, minlength=p.shape[0])

    def init(self):
        n = self.size
        self._topo = {}
        self._sparse = None
        rng = np.random.default_rng(self.seed or None)
        for name, kind, ext in INPUTS:
            x = getattr(self, name)
            if x is None:
                continue
            e = getattr(self, ext)
            if e is not None and e.size != n * x.size:
                self.fatal_error(f"{ext} must have {n} rows and {x.size} columns, not "
                                 f"shape {e.shape}")
                e = None
            p = self._projection(rng, kind, x.size)
            self._topo[name] = (e, p, self._row_counts(p))
        self._rec = {"excitatory": 1.0, "inhibitory": -1.0}.get(self.recurrent_topology, 0.0)
        self._x = np.zeros(n)
        self._weights = np.ones(n)
        window = max(1, self.moving_avg_window_size)
        self._window = np.ones((n, window))
        self._pos = np.zeros(n, dtype=int)
        self.OUTPUT[...] = 0
        self.ADENO_OUTPUT[...] = 0
        self.TETANUS[...] = 0
        self.THRESHOLD[...] = max(0.0, self.threshold)

    def _input(self, name):
        """The topology-weighted (and with scale, averaged) input per nucleus; 0 if none."""
        x = getattr(self, name)
        if x is None:
            return 0.0
        ext, projection, count = self._topo[name]
        if ext is not None:
            topo = ext.reshape(self.size, x.size).astype(np.float64)
            total = topo @ x.astype(np.float64)
            count = np.count_nonzero(topo, axis=1)
        else:
            total = projection.product(x, self._sparse)
        if self.scale:
            total = np.divide(total, count, out=np.zeros(self.size), where=count > 0)
        return total

    # --- tick -----------------------------------------------------------------------------
    def tick(self):
        out_prev = self.OUTPUT.astype(np.float64)
        weights = np.ones(self.size)
        setpoint = self._vector(self.SETPOINT, None)
        if setpoint is not None:
            rate = self._vector(self.ADAPTATIONRATE, 0.001)
            active = np.flatnonzero(out_prev > 0)
            self._window[active, self._pos[active]] = out_prev[active]
            self._pos[active] = (self._pos[active] + 1) % self._window.shape[1]
            avg = self._window.mean(axis=1)
            self._weights[active] += (setpoint[active] - avg[active]) * rate[active]
            np.clip(self._weights, WEIGHT_MIN, WEIGHT_MAX, out=self._weights)
            weights = self._weights

        thr = np.full(self.size, float(self.threshold))
        adeno = self._vector(self.ADENO_INPUT, None)
        if adeno is not None:
            thr += self.rho * adeno
        dopa = self._vector(self.DOPAMINE, None)
        if dopa is not None:
            thr -= self.sigma * dopa
        np.maximum(thr, 0.0, out=thr)

        s = 1.0 / (1.0 + np.maximum(self.psi * self._input("SHUNTING_INHIBITION"), 0.0))
        a = self.phi * weights * s * self._input("EXCITATION")
        a = a - self.chi * self._input("INHIBITION") + self.tau * self._rec * out_prev
        na = self._vector(self.NORADRENALINE, None)
        if na is not None:
            na_thr = self._vector(self.NA_THRESHOLD, NA_THRESHOLD)
            a = a + np.where(na >= na_thr, na, -na)

        tetanus = (1 - self.tetanus_leak) * self.TETANUS + self.tetanus_factor * a
        self._x += self.epsilon * (a - self._x)
        divisor = TAN_1 if self.sigmoid_divisor == "tan1" else ATAN_1
        active_out = self.alpha + self.beta * _activation(self.activation_function, self._x,
                                                          divisor)
        out = np.where(tetanus >= thr, active_out, self.alpha)
        self.TETANUS[...] = tetanus
        self.THRESHOLD[...] = thr
        self.OUTPUT[...] = out
        self.ADENO_OUTPUT[...] = out
        if self.debug:
            self.print(f"x={np.round(self._x, 4)} weights={np.round(weights, 4)} "
                       f"tetanus={np.round(tetanus, 4)} output={np.round(out, 4)}")
