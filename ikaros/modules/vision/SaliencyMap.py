"""SaliencyMap: weighted sum of feature maps, a focus, and gains learned from reward."""
from collections import deque

import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import check_gray, position_of


class SaliencyMap(Module):
    """A minimal saliency map. It has ``no_of_inputs`` feature-map inputs INPUT0,
    INPUT1, ... of one size; SALIENCE = Σ GAIN[i] · INPUTi (+ SPATIAL_BIAS when connected).
    The FOCUS, (x, y) as fractions of the map's width and height (the centre of the chosen
    pixel), is chosen by ``type``: max (the most salient pixel, the first one on ties),
    boltzmann (drawn with probability ∝ exp(salience / temperature)) or exponential (drawn
    by rank: the k-th most salient pixel with probability ∝ exp(-k / (temperature · N)) for
    N pixels, so temperature is about the fraction of the map the focus mostly falls in).
    The gains start at 1 and learn to predict reward: each feature's value at the focus is
    its mean over the square of side 2·integration_radius + 1 around it, ESTIMATION =
    Σ GAIN[i] · feature[i], and when REINFORCEMENT (its first value) is connected the gains
    move by alpha · (reinforcement - estimation) · feature for the focus chosen
    ``reinforcement_delay`` ticks before (a delta rule). ``seed`` fixes the random draws.
    (The Ikaros 2 class made its inputs in code; their names INPUT0, INPUT1, ... and the
    learning and selection formulas stated here are this module's.)"""

    integration_radius = Parameter(2, "half the side of the square that gives a feature's "
                                   "value at the focus")
    reinforcement_delay = Parameter(0, "ticks between a focus and the reward it earns")
    type = Parameter("max", "how the focus is chosen", options="max/boltzmann/exponential")
    alpha = Parameter(0.01, "learning rate of the gains")
    temperature = Parameter(0.1, "randomness of the boltzmann and exponential choices")
    no_of_inputs = Parameter(1, "number of feature maps INPUT0, INPUT1, ...")
    seed = Parameter(None, "seed of the random choices; unset (or 0) gives a different run "
                     "every time", type="int")
    REINFORCEMENT = Input("the reward for the focus chosen reinforcement_delay ticks before",
                          optional=True)
    SPATIAL_BIAS = Input("added to the salience (the size of the maps)", optional=True)
    GAIN = Output("the gain of each feature map", shape="@no_of_inputs")
    SALIENCE = Output("the salience map")
    FOCUS = Output("the focus: x, y as fractions of the width and height", shape="2")
    ESTIMATION = Output("the reward expected at the focus", shape="1")

    def configure(self):
        if self.no_of_inputs < 1:
            raise ValueError(f"no_of_inputs must be at least 1, not {self.no_of_inputs}")
        self._names = [f"INPUT{i}" for i in range(self.no_of_inputs)]
        for name in self._names:
            self.add_input(name, description="a feature map (rows, cols)")

    def set_sizes(self):
        shapes = [self.input_shape(n) for n in self._names]
        if all(shapes):
            for name, shape in zip(self._names, shapes):
                check_gray(shape, name)
            if len(set(shapes)) > 1:
                raise ValueError(f"the feature maps must have one size, not {shapes}")
            bias = self.input_shape("SPATIAL_BIAS")
            if bias and bias != shapes[0]:
                raise ValueError(f"SPATIAL_BIAS must have the size of the maps {shapes[0]}, "
                                 f"not {bias}")
            self.set_output_shape("SALIENCE", shapes[0])

    def init(self):
        self._maps = [getattr(self, name) for name in self._names]
        self._rng = np.random.default_rng(self.seed or None)
        self._history = deque(maxlen=self.reinforcement_delay + 1)
        self.GAIN.fill(1.0)

    def tick(self):
        salience = self.SALIENCE
        salience.fill(0.0)
        for gain, feature in zip(self.GAIN, self._maps):
            salience += gain * feature
        if self.SPATIAL_BIAS is not None:
            salience += self.SPATIAL_BIAS
        row, col = self._choose(salience)
        rows, cols = salience.shape
        self.FOCUS[:] = position_of(row, col, rows, cols)
        r = self.integration_radius
        window = (slice(max(row - r, 0), row + r + 1), slice(max(col - r, 0), col + r + 1))
        features = np.array([float(m[window].mean()) for m in self._maps])
        self.ESTIMATION[0] = float(self.GAIN @ features)
        self._history.append(features)
        if self.REINFORCEMENT is not None and len(self._history) == self._history.maxlen:
            past = self._history[0]
            error = float(self.REINFORCEMENT.flat[0]) - float(self.GAIN @ past)
            self.GAIN += self.alpha * error * past

    def _choose(self, salience):
        flat = salience.ravel()
        if self.type == "max":
            index = int(np.argmax(flat))
        elif self.type == "boltzmann":
            weights = np.exp((flat - flat.max()) / self.temperature)
            index = int(self._rng.choice(flat.size, p=weights / weights.sum()))
        else:
            order = np.argsort(-flat, kind="stable")
            weights = np.exp(-np.arange(flat.size) / (self.temperature * flat.size))
            index = int(order[self._rng.choice(flat.size, p=weights / weights.sum())])
        return divmod(index, salience.shape[1])
