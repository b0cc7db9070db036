"""Autoassociator: a Hebbian auto-associative network that completes stored patterns."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

RATE = 0.1          # the fraction of the way the state moves towards its target on each tick


def _size(shape):
    return int(np.prod(shape)) if shape else 0


class Autoassociator(Module):
    """A Hebbian auto-associative network of one unit per element of INPUT, working with the
    bipolar code v = 2 x - 1 of its 0..1 patterns. Learning: on every tick the weights W grow
    by ``learning_rate`` * g * (2 post - 1)(2 pre - 1)^T (no self-connections), where g is the
    first element of LEARNING-GAIN (1 when unconnected), pre is T-INPUT (or DELAYED-T-INPUT
    when connected, to learn transitions) and post is T-TARGET when connected
    (hetero-association) or T-INPUT; without T-INPUT nothing is learned. The auxiliary weights
    U from AUX-T-INPUT to AUX-T-OUTPUT (or to the post pattern) are learned the same way and
    kept in [-1, 1]. Recall: the state s (OUTPUT, 0..1, starting at the rest value 0.5) moves
    0.1 of the way towards 1/(1 + exp(-a NET)) per tick, with NET = (W * (1 - W_DEPRESSION))
    (2 s - 1) + (U * (1 - U_DEPRESSION)) (2 AUX-INPUT - 1) + INPUT + TOP-DOWN-INPUT + noise,
    a = ``activation_gain`` times ACTIVATION-GAIN's first element, and Gaussian noise of
    standard deviation ``noise_level`` (the same ``seed`` gives the same run). So a partial or
    noisy INPUT settles into the stored pattern it is closest to. The depression traces move
    ``depression_rate`` of the way towards |(2 s - 1)(2 s - 1)^T| (and |(2 s - 1)(2 AUX-INPUT -
    1)^T|) on every tick, so a pattern that has been held for long weakens its own weights and
    lets the network move on. A first element of RESET other than 0 sets the state back to 0.5
    first. ENERGY is -0.5 v^T W v with v = 2 s - 1; T-OUTPUT is 1/(1 + exp(-a W (2 T-INPUT -
    1))), the one-step recall of the training pattern; AUX-OUTPUT is 1/(1 + exp(-a U (2
    AUX-INPUT - 1))); ERROR-OUTPUT is W^T TOP-DOWN-ERROR, the error passed to lower layers.
    Outputs that need an unconnected input stay 0. The class is not in Ikaros 3; of Ikaros 2's
    the catalogue gives only its ports, parameters and a summary (Hebbian learning with a
    depression trace, completion of a partial pattern, an energy), and the golden files have
    no case of it (it draws random numbers), so these formulas are this project's reading,
    and its noise comes from NumPy's generator, not the original's."""

    learning_rate = Parameter(0.001, "the Hebbian learning rate", range=(0, None))
    depression_rate = Parameter(0.01, "how fast the depression traces follow the co-activity "
                                "(0: no depression)")
    activation_gain = Parameter(1.0, "the slope of the units' logistic activation function")
    noise_level = Parameter(0.01, "standard deviation of the Gaussian noise added to NET")
    seed = Parameter(None, "seed of the noise; unset (or 0) gives a different run every time",
                     type="int")

    INPUT = Input("the cue: external input to each unit")
    RESET = Input("sets the state to 0 on ticks where the first element is not 0",
                  optional=True)
    T_INPUT = Input("the training pattern (0/1)", optional=True, name="T-INPUT")
    T_TARGET = Input("the pattern to associate with T-INPUT; unconnected: T-INPUT itself",
                     optional=True, name="T-TARGET")
    DELAYED_T_INPUT = Input("the previous training pattern: when connected, the network "
                            "learns to go from it to the current one", optional=True,
                            name="DELAYED-T-INPUT")
    TOP_DOWN_INPUT = Input("influence from higher levels, added to NET", optional=True,
                           name="TOP-DOWN-INPUT")
    TOP_DOWN_ERROR = Input("error from higher levels, passed back through W to ERROR-OUTPUT",
                           optional=True, name="TOP-DOWN-ERROR")
    LEARNING_GAIN = Input("multiplies the learning rate by its first element", optional=True,
                          name="LEARNING-GAIN")
    ACTIVATION_GAIN = Input("multiplies activation_gain by its first element", optional=True,
                            name="ACTIVATION-GAIN")
    AUX_INPUT = Input("auxiliary input, through the weights U", optional=True,
                      name="AUX-INPUT")
    AUX_T_INPUT = Input("auxiliary training input: the pre-synaptic side of U", optional=True,
                        name="AUX-T-INPUT")
    AUX_T_OUTPUT = Input("the pattern U should give for AUX-T-INPUT; unconnected: the "
                         "training pattern", optional=True, name="AUX-T-OUTPUT")

    OUTPUT = Output("the state of the units, 0..1", size_set="INPUT")
    NET = Output("the net input of each unit on this tick", size_set="INPUT")
    ENERGY = Output("the energy -0.5 s^T W s of the state", size="1")
    T_OUTPUT = Output("the one-step recall of T-INPUT", size_set="INPUT", name="T-OUTPUT")
    ERROR_OUTPUT = Output("TOP-DOWN-ERROR passed back through W", size_set="INPUT",
                          name="ERROR-OUTPUT")
    AUX_OUTPUT = Output("the response to AUX-INPUT alone", size_set="INPUT",
                        name="AUX-OUTPUT")
    W = Output("the weights, one row per unit (post) and one column per input (pre)")
    U = Output("the auxiliary weights, one row per unit and one column per auxiliary input")
    W_DEPRESSION = Output("the depression trace of each weight in W, 0..1")
    U_DEPRESSION = Output("the depression trace of each weight in U, 0..1")

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        aux, aux_t = self.input_shape("AUX-INPUT"), self.input_shape("AUX-T-INPUT")
        if shape is None or aux is None or aux_t is None:
            return
        n = _size(shape)
        m = _size(aux_t) or _size(aux)
        self.set_output_shape("W", (n, n))
        self.set_output_shape("W_DEPRESSION", (n, n))
        self.set_output_shape("U", (n, m))
        self.set_output_shape("U_DEPRESSION", (n, m))

    def init(self):
        self._n = self.INPUT.size
        self._m = self.U.shape[1]
        for name in ("T-INPUT", "T-TARGET", "DELAYED-T-INPUT", "TOP-DOWN-INPUT",
                     "TOP-DOWN-ERROR"):
            port = getattr(self, name.replace("-", "_"))
            if port is not None and port.size != self._n:
                self.fatal_error(f"{name} has {port.size} elements; INPUT has {self._n}")
        for name in ("AUX-INPUT", "AUX-T-INPUT"):
            port = getattr(self, name.replace("-", "_"))
            if port is not None and port.size != self._m:
                self.fatal_error(f"{name} has {port.size} elements; expected {self._m}")
        if self.AUX_T_OUTPUT is not None and self.AUX_T_OUTPUT.size != self._n:
            self.fatal_error(f"AUX-T-OUTPUT has {self.AUX_T_OUTPUT.size} elements; INPUT has "
                             f"{self._n}")
        self._rng = np.random.default_rng(self.seed or None)
        self._w = self.W.reshape(self._n, self._n)
        self._u = self.U
        self._state = self.OUTPUT.reshape(-1)
        self._no_self = 1 - np.eye(self._n, dtype=np.float32)
        self._state[...] = 0.5                  # the rest state: 2 s - 1 = 0

    @staticmethod
    def _flat(port):
        return None if port is None else port.reshape(-1)

    @staticmethod
    def _bipolar(x):
        return 2 * x.reshape(-1) - 1

    def _gain(self):
        g = self.activation_gain
        return g if self.ACTIVATION_GAIN is None else g * float(self.ACTIVATION_GAIN.flat[0])

    def _f(self, net):
        z = np.clip(self._gain() * net, -60, 60)
        return 1 / (1 + np.exp(-z))

    def _learn(self):
        if self.T_INPUT is None:
            return
        rate = self.learning_rate
        if self.LEARNING_GAIN is not None:
            rate *= float(self.LEARNING_GAIN.flat[0])
        if rate == 0:
            return
        post = self._bipolar(self.T_TARGET if self.T_TARGET is not None else self.T_INPUT)
        pre = self._bipolar(self.DELAYED_T_INPUT if self.DELAYED_T_INPUT is not None
                            else self.T_INPUT)
        self._w += rate * np.outer(post, pre) * self._no_self
        if self.AUX_T_INPUT is not None and self._m:
            aux_post = self._bipolar(self.AUX_T_OUTPUT) if self.AUX_T_OUTPUT is not None \
                else post
            self._u += rate * np.outer(aux_post, self._bipolar(self.AUX_T_INPUT))
            np.clip(self._u, -1, 1, out=self._u)

    def tick(self):
        self._learn()
        s = self._state
        if self.RESET is not None and self.RESET.flat[0] != 0:
            s[...] = 0.5
        w_eff = self._w * (1 - self.W_DEPRESSION)
        net = w_eff @ (2 * s - 1) + self.INPUT.reshape(-1)
        aux = self._flat(self.AUX_INPUT)
        if aux is not None:
            aux = 2 * aux - 1
        if aux is not None and self._m:
            net += (self._u * (1 - self.U_DEPRESSION)) @ aux
        if self.TOP_DOWN_INPUT is not None:
            net += self.TOP_DOWN_INPUT.reshape(-1)
        if self.noise_level:
            net += self.noise_level * self._rng.standard_normal(self._n).astype(np.float32)
        self.NET.reshape(-1)[...] = net
        s += RATE * (self._f(net) - s)
        v = 2 * s - 1
        if self.depression_rate:
            d = self.depression_rate
            self.W_DEPRESSION.reshape(self._n, self._n)[...] += d * (
                np.abs(np.outer(v, v)) - self.W_DEPRESSION)
            if aux is not None and self._m:
                self.U_DEPRESSION[...] += d * (np.abs(np.outer(v, aux)) - self.U_DEPRESSION)
        self.ENERGY[0] = -0.5 * float(v @ self._w @ v)
        if self.T_INPUT is not None:
            self.T_OUTPUT.reshape(-1)[...] = self._f(self._w @ self._bipolar(self.T_INPUT))
        if aux is not None and self._m:
            self.AUX_OUTPUT.reshape(-1)[...] = self._f(self._u @ aux)
        if self.TOP_DOWN_ERROR is not None:
            self.ERROR_OUTPUT.reshape(-1)[...] = self._w.T @ self.TOP_DOWN_ERROR.reshape(-1)
