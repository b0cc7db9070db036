"""Arbiter: selects between, or blends, several inputs."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Arbiter(Module):
    """Selects among ``no_of_inputs`` inputs INPUT_1, INPUT_2, ... of the same size, or
    blends them. Each input gets an amplitude: the value on VALUE_k when the VALUE inputs are
    connected (all or none of them), otherwise the norm of INPUT_k (``metric`` 1: the sum of
    absolute values; 2: the euclidean norm). The amplitudes are then arbitrated: WTA keeps
    only the largest (INPUT_1 wins ties); hysteresis keeps the current winner until another
    amplitude exceeds it by more than ``hysteresis_threshold`` (or the winner's amplitude is
    0); softmax keeps all, each raised to ``softmax_exponent`` (negative amplitudes count as
    0); hierarchy keeps the input with the highest index whose amplitude is above 0
    (subsumption), else INPUT_1. The arbitration state is smoothed over time, SMOOTHED <-
    (1-a) SMOOTHED + a ARBITRATION with a = 1/switch_time when switch_time is set and
    ``alpha`` otherwise (a = 1: no smoothing), then divided by the sum of its absolute values
    to give NORMALIZED, the weights of the convex combination of the inputs on OUTPUT.
    Ikaros 2 declares the output VALUE but never writes it: it is 0 (golden files), and so
    it is here; ``value_output="strength"`` (this project's) makes it the sum of the
    absolute values of SMOOTHED, which without smoothing is the winner's amplitude. With
    ``by_row`` every row of the inputs is arbitrated on its own, as if there
    were one arbiter per row: the state outputs get one row per input row and VALUE_k gives
    one value per row (a single value is used for every row).

    Two interfaces: Ikaros 2 connects the inputs to INPUT_1 ... INPUT_n (n is
    ``no_of_inputs``, and every one must be connected), Ikaros 3 connects them all to the
    one stacked INPUT, where each connection is one input, in connection order (n is the
    number of connections and ``no_of_inputs`` is not used). A model uses one or the other.
    With INPUT the amplitudes are the norms (the VALUE_k inputs belong to the Ikaros 2
    interface).

    In an Ikaros 3 file (dialect 3) the class is Ikaros 3's: there are no INPUT_k / VALUE_k
    ports; VALUE is an input with one value per candidate (connections stacked with
    ``stack_values``; else several connections overlay, as into any input of an Ikaros 3
    file, and one connection brings all the values), and there is no VALUE output. Softmax raises the
    amplitudes themselves to the exponent (a negative amplitude with a fractional exponent
    gives NaN), NORMALIZED divides SMOOTHED by its sum (not the sum of absolute values; all
    0 when that sum is at most float32 epsilon), and by_row is not used."""

    no_of_inputs = Parameter(2, "the number of inputs (INPUT_1, INPUT_2, ...)", type="int")
    metric = Parameter("1", "the norm used as amplitude when the VALUE inputs are not "
                       "connected: 1 city block, 2 euclidean", options="1/2")
    arbitration = Parameter("WTA", "how the amplitudes are arbitrated",
                            options="WTA/hysteresis/softmax/hierarchy")
    by_row = Parameter(False, "arbitrate every row of the inputs on its own")
    softmax_exponent = Parameter(2.0, "the exponent of the amplitudes for softmax")
    hysteresis_threshold = Parameter(5.0, "how much a new amplitude must exceed the current "
                                     "winner's to take over, for hysteresis")
    switch_time = Parameter(0, "ticks over which a switch is smoothed (sets alpha to "
                            "1/switch_time); 0 uses alpha", type="int")
    alpha = Parameter(1.0, "the smoothing constant: the weight of the new arbitration state; "
                      "1 means no smoothing")
    value_output = Parameter("zero", "Ikaros 2 file: what the VALUE output holds: zero (the "
                             "original never writes it) or strength (the sum of the absolute "
                             "smoothed state)", options="zero/strength")
    debug = Parameter(False, "print the state on every tick")
    stack_inputs = Parameter(True, "Ikaros 3: each connection to INPUT is one candidate "
                             "(always so here)")
    stack_values = Parameter(False, "Ikaros 3: each connection to VALUE is one candidate's "
                             "value (stacked); without it one connection brings them all")

    INPUT = Input("Ikaros 3: all the inputs, one connection each, stacked", optional=True,
                  stack=True)
    AMPLITUDES = Output("the amplitude of each input (its value or its norm)")
    ARBITRATION = Output("the amplitudes after arbitration")
    SMOOTHED = Output("the arbitration state smoothed over time")
    NORMALIZED = Output("the smoothed state divided by its sum: the weights of the inputs")
    OUTPUT = Output("the weighted combination of the inputs")

    def configure(self):
        if self.dialect == "3":
            self.add_input("VALUE", optional=True, stack=bool(self.stack_values),
                           description="one value per candidate; without it the "
                           "candidates' norms are used")
            return
        self.add_output("VALUE", description="0, as in Ikaros 2; with value_output=strength "
                        "the sum of the absolute smoothed state")
        if self.no_of_inputs < 1:
            raise ValueError(f"no_of_inputs must be at least 1, not {self.no_of_inputs}")
        for k in range(1, self.no_of_inputs + 1):
            self.add_input(f"INPUT_{k}", optional=True,
                           description=f"Ikaros 2: input number {k} (required unless "
                           f"INPUT is used)")
            self.add_input(f"VALUE_{k}", optional=True,
                           description=f"the value of INPUT_{k}; without it the input's norm "
                           f"is used")

    def _numbered(self, name):
        return [f"{name}_{k}" for k in range(1, self.no_of_inputs + 1)]

    def set_sizes(self):
        if self.dialect == "3" and not self.connected("INPUT"):
            raise ValueError("INPUT is not connected (an Ikaros 3 Arbiter takes every "
                             "candidate on INPUT)")
        if self.connected("INPUT"):
            both = [p for p in self._numbered("INPUT") + self._numbered("VALUE")
                    if self.dialect != "3" and self.connected(p)]
            if both:
                raise ValueError(f"connect the inputs either to INPUT (Ikaros 3) or to "
                                 f"INPUT_1 ... (Ikaros 2), not both: {', '.join(both)} "
                                 f"is connected")
            stacked = self.input_shape("INPUT")
            if stacked is None:
                return
            n, shapes = stacked[0], [stacked[1:]] * stacked[0]
        else:
            missing = [p for p in self._numbered("INPUT") if not self.connected(p)]
            if missing:
                raise ValueError(f'input "{missing[0]}" is not connected (connect '
                                 f'INPUT_1 ... INPUT_{self.no_of_inputs}, or use INPUT)')
            n = self.no_of_inputs
            shapes = [self.input_shape(p) for p in self._numbered("INPUT")]
            if any(s is None for s in shapes):
                return
        sizes = [int(np.prod(s)) if s else 0 for s in shapes]
        if len(set(sizes)) != 1:
            raise ValueError(f"the inputs must have the same size; their shapes are {shapes}")
        shape = shapes[0]
        rows = (int(np.prod(shape[:-1])) if len(shape) >= 2 else 1) \
            if self.by_row and self.dialect != "3" else None
        self.set_output_shape("OUTPUT", shape)
        for name in ("AMPLITUDES", "ARBITRATION", "SMOOTHED", "NORMALIZED"):
            self.set_output_shape(name, (rows, n) if rows is not None else (n,))
        if self.dialect != "3":
            self.set_output_shape("VALUE", (rows,) if rows is not None else (1,))

    def init(self):
        self._n = n = self.AMPLITUDES.shape[-1]
        self._v3 = self.dialect == "3"
        self._rows = rows = 1 if self._v3 else self.VALUE.size
        cols = self.OUTPUT.size // rows
        if self._v3:
            self._inputs = [self.INPUT[k].reshape(rows, cols) for k in range(n)]
            values = [None] * n if self.VALUE is None else \
                [self.VALUE.reshape(-1)[k:k + 1] for k in range(n)]
            if self.VALUE is not None and self.VALUE.size != n:
                self.fatal_error(f"VALUE has {self.VALUE.size} elements; it needs one per "
                                 f"candidate ({n})")
                return
        elif self.INPUT is not None:
            self._inputs = [self.INPUT[k].reshape(rows, cols) for k in range(n)]
            values = [None] * n
        else:
            self._inputs = [getattr(self, p).reshape(rows, cols)
                            for p in self._numbered("INPUT")]
            values = [getattr(self, p) for p in self._numbered("VALUE")]
        connected = sum(v is not None for v in values)
        if connected not in (0, n):
            self.fatal_error("connect all VALUE inputs or none of them")
            return
        self._values = [v.reshape(-1) for v in values] if connected else None
        if self._values is not None:
            for k, v in enumerate(self._values, 1):
                if v.size != 1 and v.size < rows:
                    self.fatal_error(f"VALUE_{k} has {v.size} elements; it needs 1 or {rows}")
                    return
        self._x = np.zeros((n, rows, cols), np.float32)
        self._amp = self.AMPLITUDES.reshape(rows, n)
        self._arb = self.ARBITRATION.reshape(rows, n)
        self._smooth = self.SMOOTHED.reshape(rows, n)
        self._norm = self.NORMALIZED.reshape(rows, n)
        self._out = self.OUTPUT.reshape(rows, cols)
        self._winner = np.zeros(rows, np.intp)
        self._row_index = np.arange(rows)

    def _keep_only(self, index):
        """Arbitration state with only the amplitude at ``index`` (per row) kept."""
        self._arb.fill(0)
        r = self._row_index
        self._arb[r, index] = self._amp[r, index]

    def tick(self):
        n, rows = self._n, self._rows
        for k in range(n):
            self._x[k] = self._inputs[k]
        # amplitudes
        if self._values is not None:
            for k, v in enumerate(self._values):
                self._amp[:, k] = v[:rows] if v.size >= rows else v[0]
        elif self.metric == "2":
            self._amp[...] = np.sqrt(np.sum(self._x * self._x, axis=2)).T
        else:
            self._amp[...] = np.sum(np.abs(self._x), axis=2).T
        # arbitration
        method = self.arbitration
        if method == "hysteresis":
            best = np.argmax(self._amp, axis=1)
            r = self._row_index
            current = self._amp[r, self._winner]
            switch = (self._amp[r, best] > current + self.hysteresis_threshold) | (current == 0)
            self._winner = np.where(switch, best, self._winner)
            self._keep_only(self._winner)
        else:
            self._winner[...] = 0
            if method == "softmax":
                with np.errstate(invalid="ignore"):
                    np.power(self._amp if self._v3 else np.maximum(self._amp, 0),
                             self.softmax_exponent, out=self._arb)
            elif method == "hierarchy":
                positive = self._amp > 0
                last = n - 1 - np.argmax(positive[:, ::-1], axis=1)
                self._keep_only(np.where(positive.any(axis=1), last, 0))
            else:
                self._keep_only(np.argmax(self._amp, axis=1))
        # smoothing
        a = 1.0 / self.switch_time if self.switch_time > 0 else self.alpha
        if a != 1.0:
            self._smooth *= np.float32(1.0 - a)
            self._smooth += np.float32(a) * self._arb
        else:
            self._smooth[...] = self._arb
        # normalization and the convex combination
        if self._v3:
            total = np.sum(self._smooth, axis=1, keepdims=True)
            empty = total <= np.finfo(np.float32).eps
        else:
            total = np.sum(np.abs(self._smooth), axis=1, keepdims=True)
            empty = total == 0
        np.divide(self._smooth, total, out=self._norm, where=~empty)
        self._norm[empty[:, 0]] = 0
        np.einsum("rk,krc->rc", self._norm, self._x, out=self._out)
        if not self._v3:
            self.VALUE[...] = total[:, 0] if self.value_output == "strength" else 0
        if self.debug:
            self.print(f"amplitudes {self.AMPLITUDES.tolist()} normalized "
                       f"{self.NORMALIZED.tolist()} output {self.OUTPUT.tolist()}")
