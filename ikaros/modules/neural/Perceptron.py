"""Perceptron: a single layer of perceptron-like units with a choice of learning rules."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from .._crand import numpy_generator, uses_crand

_ZERO_ONE = ("step", "sigmoid")          # activations whose targets are 0/1 (the others -1/1)


class Perceptron(Module):
    """A single layer of perceptron units, one per element of T_TARGET, each with a weight
    per input element and a bias weight (on a fixed input ``bias``). On every tick where
    TRAIN's first element is not 0 (every tick when TRAIN is not connected) the layer learns
    from the pair T_INPUT -> T_TARGET: ERROR is then the root of the summed squared
    difference between target and response, and CORRECT the percentage of the last
    ``correct_average_size`` training examples whose every unit was classified right.
    OUTPUT is then the response to INPUT with the updated weights. ``activation_type`` is step
    (1 above ``step_threshold``, else 0), sign (1 or -1), sigmoid 1/(1+exp(-beta net)) or tanh
    (tanh(beta net)); step and sigmoid expect 0/1 targets, sign and tanh -1/1 (with
    ``normalize_target`` a target > 0 reads as 1 and any other as 0 or -1). The learning rules
    follow Hassoun (1995): rosenblatt dw = r (t - y) x; rosenblatt_margin dw = r t x when
    t net <= margin; may dw = r (margin - t net) t x / |x|^2 when t net <= margin; alpha_lms
    dw = alpha (t - net) x / |x|^2; mu_lms dw = mu (t - net) x; delta dw = r (t - y) f'(net) x
    (for sigmoid or tanh units). r is ``learning_rate``, divided by 0.1 sqrt(tick + 100) or by
    0.42 ln(tick + 10) when ``learning_rate_mod`` is sqrt or log. ``learning_type`` instant
    applies each change at once, batch sums the changes of ``batch_size`` training ticks and
    applies them together, momentum adds ``momentum_ratio`` times the previous change. A bias
    of 0 is read as 1 with a warning. The class is not in Ikaros 3. The golden files show
    Ikaros 2's initial weights and responses (below) but no learning, so the learning rules
    above follow the catalogue's list of them (and Hassoun) and are this project's reading;
    the learning rate's decay factors are this project's too.

    The initial weights are uniform in [rand_weights_min, rand_weights_max]. With ``seed``
    unset (or 0) an Ikaros 2 file draws them as the original does, from the C library's
    rand() sequence (glibc's, shared with the network's other modules that draw from it):
    min + (max - min) rand() / RAND_MAX for each unit in turn, its input weights and then
    its bias weight, so that the first Perceptron of a model starts with the original's
    weights (the golden files show it). A seed above 0 gives the same weights for the same
    seed, below 0 (or unset in an Ikaros 3 file) different weights on every run.

    In an Ikaros 2 file the layer learns only on ticks where TRAIN's first element is
    exactly 1: in the golden files the original did not learn at all with 1.7, 0.5 or a
    sine on TRAIN (nor report ERROR or CORRECT), and that it learns with 1 is this project's
    reading. In an Ikaros 3 file (or with TRAIN unconnected) any value other than 0 trains
    (this project's)."""

    rand_weights_min = Parameter(-0.5, "lower limit of the random initial weights")
    rand_weights_max = Parameter(0.5, "upper limit of the random initial weights")
    learning_rate = Parameter(0.1, "the learning rate r of the rosenblatt, margin, may and "
                              "delta rules", range=(0, None))
    learning_rate_mod = Parameter("none", "how the learning rate decreases with time: none, "
                                  "sqrt (r / (0.1 sqrt(tick + 100))) or log "
                                  "(r / (0.42 ln(tick + 10)))", options="none,sqrt,log")
    bias = Parameter(1.0, "the value of the extra input that every unit has a weight for")
    learning_type = Parameter("instant", "when changes are applied: instant (default), batch "
                              "or momentum", options="default,instant,batch,momentum")
    momentum_ratio = Parameter(0.42, "with momentum learning, the part of the previous change "
                               "that is added to the current one", range=(0, 1))
    activation_type = Parameter("step", "the units' activation: step (default), sign, "
                                "sigmoid or tanh", options="default,step,sign,sigmoid,tanh")
    learning_rule = Parameter("rosenblatt", "the learning rule: rosenblatt (default), "
                              "rosenblatt_margin, may, alpha_lms, mu_lms or delta",
                              options="default,rosenblatt,rosenblatt_margin,may,alpha_lms,"
                                      "mu_lms,delta")
    batch_size = Parameter(42, "with batch learning, the number of training ticks whose "
                           "changes are summed before they are applied")
    step_threshold = Parameter(0.0, "the step activation is 1 when the net input is above this")
    margin = Parameter(0.2, "the margin of the rosenblatt_margin and may rules")
    alpha = Parameter(0.1, "the learning rate of the alpha_lms rule")
    mu = Parameter(0.1, "the learning rate of the mu_lms rule")
    beta = Parameter(1.0, "the slope of the sigmoid and tanh activations (and of the delta "
                      "rule's derivative)")
    correct_average_size = Parameter(42, "the number of recent training examples CORRECT is "
                                     "computed over")
    normalize_target = Parameter(False, "read a target > 0 as 1 and any other as 0 (step, "
                                 "sigmoid) or -1 (sign, tanh)")
    seed = Parameter(None, "seed of the random initial weights; unset or 0: Ikaros 2's rand() "
                     "sequence (Ikaros 3 file: different weights every run); below 0: "
                     "different weights every run", type="int")

    INPUT = Input("the pattern to respond to", flatten=True)
    T_INPUT = Input("the training pattern", flatten=True)
    T_TARGET = Input("the desired response to T_INPUT; its size is the number of units",
                     flatten=True)
    TRAIN = Input("learn on ticks where the first element is 1 (Ikaros 3 file: not 0); "
                  "unconnected: always", optional=True)
    OUTPUT = Output("the response of each unit to INPUT", size_set="T_TARGET")
    ERROR = Output("sqrt of the summed squared difference between T_TARGET and the response "
                   "to T_INPUT, on the last training tick", size="1")
    CORRECT = Output("percentage of the recent training examples that were classified right",
                     size="1")

    def init(self):
        n_out, n_in = self.T_TARGET.size, self.T_INPUT.size
        if self.INPUT.size != n_in:
            self.fatal_error(f"INPUT has {self.INPUT.size} elements but T_INPUT {n_in}")
        low, high = self.rand_weights_min, self.rand_weights_max
        if uses_crand(self):
            stream = self.c_random
            self._w = np.array([[np.float32(low + (high - low) * stream.uniform())
                                 for _ in range(n_in + 1)] for _ in range(n_out)], np.float64)
        else:
            self._w = numpy_generator(self).uniform(low, high, (n_out, n_in + 1))
        self._bias = self.bias
        if self._bias == 0:
            self.warning("bias 0 is not allowed; 1 is used")
            self._bias = 1.0
        self._activation = "step" if self.activation_type == "default" else self.activation_type
        self._rule = "rosenblatt" if self.learning_rule == "default" else self.learning_rule
        self._type = "instant" if self.learning_type == "default" else self.learning_type
        self._pending = np.zeros_like(self._w)        # batch sum or previous change
        self._batch_count = 0
        self._train_count = 0
        self._history = np.zeros(max(1, self.correct_average_size), dtype=bool)
        self._n_history = 0

    # --- unit functions ------------------------------------------------------------------
    def _augment(self, x):
        return np.append(np.asarray(x, dtype=np.float64), self._bias)

    def _activate(self, net):
        kind, beta = self._activation, self.beta
        if kind == "step":
            return (net > self.step_threshold).astype(np.float64)
        if kind == "sign":
            return np.where(net >= 0, 1.0, -1.0)
        if kind == "sigmoid":
            return 0.5 * (1 + np.tanh(0.5 * beta * net))     # 1/(1+exp(-beta net)), stable
        return np.tanh(beta * net)

    def _classify(self, y):
        """The class (0/1 or -1/1) a response stands for."""
        if self._activation == "sigmoid":
            return (y > 0.5).astype(np.float64)
        if self._activation == "tanh":
            return np.where(y > 0, 1.0, -1.0)
        return y

    def _target(self):
        t = self.T_TARGET.astype(np.float64)
        if self.normalize_target:
            low = 0.0 if self._activation in _ZERO_ONE else -1.0
            t = np.where(t > 0, 1.0, low)
        return t

    def _rate(self):
        tick = max(self.clock.tick, 0)
        if self.learning_rate_mod == "sqrt":
            return self.learning_rate / (0.10 * math.sqrt(tick + 100))
        if self.learning_rate_mod == "log":
            return self.learning_rate / (0.42 * math.log(tick + 10))
        return self.learning_rate

    def _change(self, x, t, net, y):
        rule, r = self._rule, self._rate()
        if rule == "rosenblatt":
            return r * np.outer(t - y, x)
        if rule == "rosenblatt_margin":
            return r * np.outer(np.where(t * net <= self.margin, t, 0.0), x)
        if rule == "may":
            amount = np.where(t * net <= self.margin, (self.margin - t * net) * t, 0.0)
            return r * np.outer(amount, x) / np.dot(x, x)
        if rule == "alpha_lms":
            return self.alpha * np.outer(t - net, x) / np.dot(x, x)
        if rule == "mu_lms":
            return self.mu * np.outer(t - net, x)
        # delta: gradient descent through the sigmoid or tanh
        if self._activation == "sigmoid":
            slope = self.beta * y * (1 - y)
        elif self._activation == "tanh":
            slope = self.beta * (1 - y * y)
        else:
            slope = np.ones_like(y)
        return r * np.outer((t - y) * slope, x)

    # --- tick ----------------------------------------------------------------------------
    def _train(self):
        x = self._augment(self.T_INPUT)
        t = self._target()
        net = self._w @ x
        y = self._activate(net)
        self.ERROR[0] = math.sqrt(float(np.sum((t - y) ** 2)))
        self._history[self._train_count % self._history.size] = bool(
            np.all(self._classify(y) == t))
        self._train_count += 1
        self._n_history = min(self._n_history + 1, self._history.size)
        self.CORRECT[0] = 100.0 * np.count_nonzero(self._history[:self._n_history]) \
            / self._n_history
        dw = self._change(x, t, net, y)
        if self._type == "instant":
            self._w += dw
        elif self._type == "momentum":
            dw = dw + self.momentum_ratio * self._pending
            self._w += dw
            self._pending = dw
        else:                                           # batch
            self._pending += dw
            self._batch_count += 1
            if self._batch_count >= max(1, self.batch_size):
                self._w += self._pending
                self._pending[...] = 0
                self._batch_count = 0

    def tick(self):
        train = self.TRAIN is None
        if not train:
            first = self.TRAIN.reshape(-1)[0]
            train = first != 0 if self.dialect == "3" else first == 1
        if train:
            self._train()
        self.OUTPUT[...] = self._activate(self._w @ self._augment(self.INPUT)).reshape(
            self.OUTPUT.shape)
