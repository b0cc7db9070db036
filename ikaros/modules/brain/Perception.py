"""Perception: a scanning perception of objects and their properties."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Perception(Module):
    """A scanning perception system (from the 2020 decision model). ENVIRONMENT has a row per
    object (location) and a column per property; a non-zero entry means the object has that
    property. FEATURES has a row per property holding its feature vector. On each tick the
    gaze shifts with probability 1 / ``interval`` (every tick when interval <= 1): an object
    is drawn, uniformly, or when LOCATION_IN is connected with probability proportional to 1
    + phi * LOCATION_IN^2; then one of its properties is drawn uniformly. OUTPUT becomes that
    property's feature vector (all 0 for an object without properties) and LOCATION_OUT is
    one-hot for the object. Between shifts the outputs keep their values; they are 0 until
    the first shift. The ``seed`` fixes the draws. LOCATION_OUT has one element per object
    and OUTPUT one per feature (Ikaros 2 declared them 2 and 8 whatever the inputs, and wrote
    past the end for larger ones). ``alpha`` and ``beta`` have no effect, as in Ikaros 2."""

    interval = Parameter(0, "mean number of ticks between gaze shifts", type="int")
    alpha = Parameter(0.0, "unused (kept so Ikaros 2 models load)")
    beta = Parameter(0.0, "unused (kept so Ikaros 2 models load)")
    phi = Parameter(0.0, "gain of the top-down spatial attention LOCATION_IN")
    seed = Parameter(None, "seed of the random choices; unset (or 0) gives a different run "
                     "every time", type="int")
    LOCATION_IN = Input("optional saliency of each object that biases where the gaze goes",
                        optional=True, flatten=True)
    ENVIRONMENT = Input("objects x properties: non-zero where an object has a property")
    FEATURES = Input("properties x features: the feature vector of each property")
    LOCATION_OUT = Output("the attended object, one-hot")
    OUTPUT = Output("the feature vector of the perceived property")

    def set_sizes(self):
        env, feat = self.input_shape("ENVIRONMENT"), self.input_shape("FEATURES")
        if env is not None:
            self.set_output_shape("LOCATION_OUT", env[0] if len(env) == 2 else 1)
        if feat is not None:
            self.set_output_shape("OUTPUT", feat[-1] if feat else 1)

    def init(self):
        self._rng = np.random.default_rng(self.seed or None)
        self._env = self.ENVIRONMENT.reshape(self.LOCATION_OUT.size, -1)
        n_props = self._env.shape[1]
        self._features = self.FEATURES.reshape(-1, self.OUTPUT.size)
        if self._features.shape[0] != n_props:
            self.fatal_error(f"FEATURES has {self._features.shape[0]} rows but ENVIRONMENT "
                             f"has {n_props} properties (columns)")
        if self.LOCATION_IN is not None and self.LOCATION_IN.size != self.LOCATION_OUT.size:
            self.fatal_error(f"LOCATION_IN has {self.LOCATION_IN.size} elements but there are "
                             f"{self.LOCATION_OUT.size} objects")
        self.LOCATION_OUT[...] = 0
        self.OUTPUT[...] = 0

    def tick(self):
        if self.interval > 1 and self._rng.random() >= 1.0 / self.interval:
            return
        n = self.LOCATION_OUT.size
        if self.LOCATION_IN is None:
            obj = int(self._rng.integers(n))
        else:
            p = 1.0 + self.phi * self.LOCATION_IN.astype(np.float64) ** 2
            p = np.maximum(p, 0.0)
            total = p.sum()
            obj = int(self._rng.choice(n, p=p / total)) if total > 0 else int(
                self._rng.integers(n))
        self.LOCATION_OUT[...] = 0
        self.LOCATION_OUT[obj] = 1
        props = np.flatnonzero(self._env[obj])
        if props.size:
            self.OUTPUT[...] = self._features[props[self._rng.integers(props.size)]]
        else:
            self.OUTPUT[...] = 0
