"""Softmax: normalises its input to a distribution."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Softmax(Module):
    """Normalises INPUT so that its elements sum to 1, over all elements whatever the shape.
    With type ``polynomial`` each element is first raised to ``exponent``, |x|^exponent
    (negative elements count by their magnitude, which for even exponents is the same as
    Ikaros 2 and for other exponents avoids NaN); with type ``exponential`` it is exp(x)
    (computed as exp(x - max) so large inputs cannot overflow; the result is the same). When
    the sum is 0, or not finite (an input that is NaN or infinite), the output is 0, with a
    warning the first time. Ikaros 2 declared the
    exponent as ``exponenet`` but read ``exponent``; both names are accepted here and
    ``exponenet`` is used when it is given a non-zero value."""

    type = Parameter("polynomial", "polynomial: |x|^exponent / sum; exponential: "
                     "exp(x) / sum", options="polynomial/exponential")
    exponent = Parameter(2.0, "the exponent of the polynomial type")
    exponenet = Parameter(None, "the misspelt Ikaros 2 name of exponent; used instead of "
                          "exponent when non-zero", type="number")
    INPUT = Input("the values to normalise")
    OUTPUT = Output("the normalised values, summing to 1 (or all 0)", size_set="INPUT")

    def init(self):
        self._x = self.INPUT.reshape(self.OUTPUT.shape)
        self._warned = False

    def tick(self):
        with np.errstate(invalid="ignore", over="ignore"):    # NaN and inf are reported
            self._normalize()

    def _normalize(self):
        x, out = self._x, self.OUTPUT
        if self.type == "exponential":
            np.subtract(x, np.max(x), out=out)
            np.exp(out, out=out)
        else:
            exponent = self.exponenet or self.exponent
            np.abs(x, out=out)
            np.power(out, np.float32(exponent), out=out)
        total = float(np.sum(out, dtype=np.float64))
        if total != 0 and np.isfinite(total):
            out *= np.float32(1.0 / total)
        else:
            out.fill(0)
            if not self._warned:
                self._warned = True
                self.warning("the sum to normalise by is 0 (or not finite); the output is 0")
