"""Threshold: applies a threshold to each element."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Threshold(Module):
    """Applies ``threshold`` to each element of INPUT. An element at or below the threshold
    gives 0. An element above it gives 1 with type ``binary``, and its distance above the
    threshold (input - threshold) with type ``linear``. With ``bypass`` the input is copied
    unchanged. The output has the input's shape."""

    bypass = Parameter(False, "copy the input to the output unchanged")
    threshold = Parameter(0.0, "the threshold")
    type = Parameter("binary", "binary: 1 above the threshold; linear: input - threshold "
                     "above it", options="binary/linear")
    INPUT = Input("the values")
    OUTPUT = Output("the thresholded values", size_set="INPUT")

    compiled_op = "threshold"   # an instruction of the compiled tick (ikaros/kernel/compiled/)

    def init(self):
        self._x = self.INPUT.reshape(self.OUTPUT.shape)

    def tick(self):
        x, out = self._x, self.OUTPUT
        if self.bypass:
            out[...] = x
        elif self.type == "linear":
            np.subtract(x, np.float32(self.threshold), out=out)
            np.maximum(out, 0, out=out)
        else:
            np.greater(x, np.float32(self.threshold), out=out)
