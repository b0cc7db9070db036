"""Softmax: normalises its input to a distribution."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Softmax(Module):
    """Normalises INPUT so that its elements sum to 1, over all elements whatever the shape.
    With type ``polynomial`` each element is first raised to ``exponent``, |x|^exponent;
    with type ``exponential`` it is exp(x) (computed as exp(x - max) so large inputs cannot
    overflow; the result is the same). When the sum is 0, or not finite (an input that is
    NaN or infinite), the output is 0, with a warning the first time.

    Ikaros 2's class file declares the exponent as ``exponenet`` (default 2) while its code
    reads ``exponent``: a file that sets ``exponent`` gets that exponent, and one that does
    not gets 0, so every element comes out 1/n (golden files). That is the default in an
    Ikaros 2 file here too; ``exponent="2"`` gives what the class file meant, and
    ``exponenet`` is accepted but, as in Ikaros 2, not used (with a warning). In an Ikaros 3
    file, whose Softmax declares no parameters and whose computation no reference gives,
    the default exponent is 2 (this project's reading). How the original treats negative
    elements with an odd or fractional exponent is not given either: they count here by
    their magnitude."""

    type = Parameter("polynomial", "polynomial: |x|^exponent / sum; exponential: "
                     "exp(x) / sum", options="polynomial/exponential")
    exponent = Parameter(0.0, "the exponent of the polynomial type (Ikaros 2 file: 0 unless "
                         "set, as in the original, which makes every element 1/n)",
                         default_v3=2.0)
    exponenet = Parameter(None, "the misspelt name Ikaros 2's class file declares; not used "
                          "(set exponent)", type="number")
    INPUT = Input("the values to normalise")
    OUTPUT = Output("the normalised values, summing to 1 (or all 0)", size_set="INPUT")

    def init(self):
        self._x = self.INPUT.reshape(self.OUTPUT.shape)
        self._warned = False
        if "exponenet" in getattr(self.element, "attrs", {}):
            self.warning("exponenet is the misspelt name that Ikaros 2 declares and never "
                         "reads; it is not used (set exponent)")

    def tick(self):
        with np.errstate(invalid="ignore", over="ignore"):    # NaN and inf are reported
            self._normalize()

    def _normalize(self):
        x, out = self._x, self.OUTPUT
        if self.type == "exponential":
            np.subtract(x, np.max(x), out=out)
            np.exp(out, out=out)
        else:
            np.abs(x, out=out)
            np.power(out, np.float32(self.exponent), out=out)
        total = float(np.sum(out, dtype=np.float64))
        if total != 0 and np.isfinite(total):
            out *= np.float32(1.0 / total)
        else:
            out.fill(0)
            if not self._warned:
                self._warned = True
                self.warning("the sum to normalise by is 0 (or not finite); the output is 0")
