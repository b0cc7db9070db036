"""Perception: a scanning perception of objects and their properties."""
import numpy as np

from ikaros.module import RAND_MAX, Input, Module, Output, Parameter

from .._crand import module_rand

LOCATIONS, FEATURE_SIZE = 2, 8      # Ikaros 2's fixed sizes of LOCATION_OUT and OUTPUT


class Perception(Module):
    """A scanning perception system (from the 2020 decision model; Ikaros 3 has no such
    class). On each tick the gaze shifts with probability 1 / ``interval`` (every tick when
    interval <= 1); between shifts the outputs keep their values (0 until the first).

    ``scan`` = ``original`` (Ikaros 2): LOCATION_OUT has 2 elements and OUTPUT 8. Each tick
    the C library's rand() of the network (as Ikaros 2, unseeded; ``seed`` gives the module
    a stream of its own) is drawn three times: the first decides the shift (rand()/RAND_MAX
    below 1 / interval), the second the location (rand() % 2; with LOCATION_IN connected and
    phi not 0, location 1 with probability proportional to 1 + phi * LOCATION_IN[1]^2
    against 1 + phi * LOCATION_IN[0]^2, by rand()/RAND_MAX), the third a row r of FEATURES
    (rand() % its rows); LOCATION_OUT is one-hot for the location and OUTPUT the 8 values
    of FEATURES from the start of row r on (0 past its end). The golden file of Ikaros 2
    shows the three draws, the sizes and OUTPUT for a FEATURES of 3 rows of 4 (the same
    number of rows as ENVIRONMENT there, so it does not tell which of the two sets the
    count) with the default interval and no LOCATION_IN; the shift probability and
    LOCATION_IN's weighting are this project's reading of the class description, and
    ENVIRONMENT is not used.

    ``scan`` = ``objects`` (this project's): ENVIRONMENT has a row per object (location)
    and a column per property, non-zero where the object has it; FEATURES a row per
    property with its feature vector. An object is drawn uniformly, or when LOCATION_IN is
    connected with probability proportional to 1 + phi * LOCATION_IN^2, then one of its
    properties uniformly; OUTPUT is that property's feature vector (0 for an object
    without properties) and LOCATION_OUT (one element per object) is one-hot for the
    object; the draws come from a generator seeded with ``seed``.

    ``alpha`` and ``beta`` have no effect, as in Ikaros 2."""

    scan = Parameter("original", "original: Ikaros 2's scan (2 locations, 8 features); "
                     "objects: one location per object, its properties' features",
                     options="original,objects")
    interval = Parameter(0, "mean number of ticks between gaze shifts", type="int")
    alpha = Parameter(0.0, "unused (kept so Ikaros 2 models load)")
    beta = Parameter(0.0, "unused (kept so Ikaros 2 models load)")
    phi = Parameter(0.0, "gain of the top-down spatial attention LOCATION_IN")
    seed = Parameter(None, "seed of the random choices; unset (or 0): original, the "
                     "network's C rand() as Ikaros 2; objects, a different run every time",
                     type="int")
    LOCATION_IN = Input("optional saliency of each location that biases where the gaze goes",
                        optional=True, flatten=True)
    ENVIRONMENT = Input("objects x properties: non-zero where an object has a property")
    FEATURES = Input("properties x features: the feature vector of each property")
    LOCATION_OUT = Output("the attended location, one-hot")
    OUTPUT = Output("the feature vector of the perceived property")

    def set_sizes(self):
        if self.scan == "original":
            self.set_output_shape("LOCATION_OUT", LOCATIONS)
            self.set_output_shape("OUTPUT", FEATURE_SIZE)
            return
        env, feat = self.input_shape("ENVIRONMENT"), self.input_shape("FEATURES")
        if env is not None:
            self.set_output_shape("LOCATION_OUT", env[0] if len(env) == 2 else 1)
        if feat is not None:
            self.set_output_shape("OUTPUT", feat[-1] if feat else 1)

    def init(self):
        if self.scan == "original":
            self._random = module_rand(self)
            self._features = self.FEATURES.reshape(self.FEATURES.shape[0]
                                                   if self.FEATURES.ndim else 1, -1)
        else:
            self._init_objects()
        self.LOCATION_OUT[...] = 0
        self.OUTPUT[...] = 0

    def _init_objects(self):
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

    def _attention(self, n):
        """The weights of the n locations, or None without LOCATION_IN (or phi 0)."""
        if self.LOCATION_IN is None or not self.phi:
            return None
        weights = np.ones(n)
        m = min(n, self.LOCATION_IN.size)
        weights[:m] += self.phi * self.LOCATION_IN[:m].astype(np.float64) ** 2
        weights = np.maximum(weights, 0.0)
        return weights / weights.sum() if weights.sum() > 0 else None

    def tick(self):
        if self.scan == "original":
            self._tick_original()
            return
        if self.interval > 1 and self._rng.random() >= 1.0 / self.interval:
            return
        n = self.LOCATION_OUT.size
        p = self._attention(n)
        obj = int(self._rng.integers(n)) if p is None else int(self._rng.choice(n, p=p))
        self.LOCATION_OUT[...] = 0
        self.LOCATION_OUT[obj] = 1
        props = np.flatnonzero(self._env[obj])
        if props.size:
            self.OUTPUT[...] = self._features[props[self._rng.integers(props.size)]]
        else:
            self.OUTPUT[...] = 0

    def _tick_original(self):
        rand = self._random
        shift = rand.uniform()
        if self.interval > 1 and shift >= 1.0 / self.interval:
            return
        p = self._attention(LOCATIONS)
        draw = rand.rand()
        location = draw % LOCATIONS if p is None else int(draw / RAND_MAX >= p[0])
        row = rand.rand() % max(self._features.shape[0], 1)
        values = self._features.reshape(-1)[row * self._features.shape[1]:][:FEATURE_SIZE]
        self.LOCATION_OUT[...] = 0
        self.LOCATION_OUT[location] = 1
        self.OUTPUT[...] = 0
        self.OUTPUT[:values.size] = values
