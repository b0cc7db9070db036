"""BackProp: a multilayer perceptron with one hidden layer, trained by back-propagation."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class BackProp(Module):
    """A multilayer perceptron with one hidden layer of ``hidden_units`` logistic units and one
    logistic output unit per element of T_TARGET (targets in 0..1); every unit has a bias.
    On every tick OUTPUT is the network's response to INPUT, and then the network takes one
    on-line back-propagation step on the pair T_INPUT -> T_TARGET (gradient descent on the
    squared error with learning rate ``lr`` and ``momentum`` times the previous change
    added). ERROR is the Euclidean norm of the difference between T_TARGET and the response
    to T_INPUT before the step. That OUTPUT comes before the tick's step and that ERROR is a
    norm is what the Ikaros 2 golden files show; the class is not in Ikaros 3. The original's
    initial weights are the same on every run and in its two models of the same sizes, and
    small (its outputs at a zero INPUT are 0.49 to 0.53, as from weights of about +-0.05),
    but the order and formula it draws them by are not known: no layout of the weights
    (either layer first, row or column order, the bias first, last or absent) filled from
    glibc's rand() / RAND_MAX, scaled, or from Gaussian numbers made from it (Box-Muller,
    Marsaglia's polar method), from any of its first 150 draws on, gives its outputs. Its
    learning rule is not documented either (its first step agrees with the one here for lr
    times the sum of the squared hidden outputs of about 0.65), so this class does not
    reproduce the original's numbers: here the initial weights are uniform in [-0.5, 0.5]
    from NumPy's generator (the same ``seed`` gives the same run; unset or 0, a different
    run every time). (The catalogue gives ``lr`` no default; here it is a
    number, 0.2.)"""

    lr = Parameter(0.2, "the learning rate", range=(0, None))
    momentum = Parameter(0.0, "the part of the previous weight change added to the current one",
                         range=(0, 1))
    hidden_units = Parameter(10, "the number of hidden units")
    seed = Parameter(None, "seed of the random initial weights; unset (or 0) gives a "
                     "different run every time", type="int")

    INPUT = Input("the pattern to respond to", flatten=True)
    T_INPUT = Input("the training pattern", flatten=True)
    T_TARGET = Input("the desired response to T_INPUT (0..1); its size is the number of "
                     "output units", flatten=True)
    OUTPUT = Output("the network's response to INPUT", size_set="T_TARGET")
    ERROR = Output("the norm of the training error on this tick, before the weight change",
                   size="1")

    def init(self):
        n_in, n_out, n_hidden = self.T_INPUT.size, self.T_TARGET.size, max(1, self.hidden_units)
        if self.INPUT.size != n_in:
            self.fatal_error(f"INPUT has {self.INPUT.size} elements but T_INPUT {n_in}")
        rng = np.random.default_rng(self.seed or None)
        # weights include a bias column (last)
        self._w1 = rng.uniform(-0.5, 0.5, (n_hidden, n_in + 1))
        self._w2 = rng.uniform(-0.5, 0.5, (n_out, n_hidden + 1))
        self._d1 = np.zeros_like(self._w1)
        self._d2 = np.zeros_like(self._w2)

    @staticmethod
    def _sigmoid(x):
        return 0.5 * (1 + np.tanh(0.5 * x))

    def _forward(self, x):
        x1 = np.append(np.asarray(x, dtype=np.float64), 1.0)
        h = np.append(self._sigmoid(self._w1 @ x1), 1.0)
        return x1, h, self._sigmoid(self._w2 @ h)

    def tick(self):
        self.OUTPUT[...] = self._forward(self.INPUT)[2].reshape(self.OUTPUT.shape)
        x1, h, y = self._forward(self.T_INPUT)
        t = self.T_TARGET.astype(np.float64)
        self.ERROR[0] = np.sqrt(np.sum((t - y) ** 2))
        delta_out = (t - y) * y * (1 - y)
        delta_hidden = (self._w2[:, :-1].T @ delta_out) * h[:-1] * (1 - h[:-1])
        self._d2 = self.lr * np.outer(delta_out, h) + self.momentum * self._d2
        self._d1 = self.lr * np.outer(delta_hidden, x1) + self.momentum * self._d1
        self._w2 += self._d2
        self._w1 += self._d1
