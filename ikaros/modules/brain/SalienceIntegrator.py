"""SalienceIntegrator: a decaying weighted sum of stacked salience maps (Ikaros 3)."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class SalienceIntegrator(Module):
    """Each tick multiplies the previous output by ``decay`` and adds the salience maps
    connected to INPUT (one connection per map), each weighted by its element of
    ``factors`` (a map without a factor gets 1). The output has the shape of one map. New in
    Ikaros 3."""

    factors = Parameter("1", "the weight of each map, in connection order", type="array")
    decay = Parameter(0.9, "the factor the previous output is multiplied by")
    INPUT = Input("the salience maps, one connection each, stacked", stack=True)
    OUTPUT = Output("the integrated salience, shaped like one map")

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape is not None:
            self.set_output_shape("OUTPUT", shape[1:] or (1,))

    def init(self):
        n = self.INPUT.shape[0]
        given = np.ravel(self.factors).astype(np.float32)[:n]
        self._factors = np.concatenate([given, np.ones(n - given.size, np.float32)])
        self.OUTPUT[...] = 0

    def tick(self):
        self.OUTPUT *= np.float32(self.decay)
        self.OUTPUT += np.tensordot(self._factors, self.INPUT, axes=1).reshape(
            self.OUTPUT.shape)
