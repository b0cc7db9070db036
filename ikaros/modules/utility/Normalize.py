"""Normalize: scales the input to a standard range or norm."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Normalize(Module):
    """Normalises the whole input. ``range`` maps the smallest element to 0 and the largest
    to 1; ``euclidean`` divides by the Euclidean (L2) norm, so the output has length 1;
    ``cityblock`` divides by the sum of absolute values (L1 norm); ``max`` divides by the
    largest element. When the divisor is 0 (a constant input for ``range``, an all-zero
    input otherwise) the output is 0 and a warning is given once. The arithmetic is done in
    double precision, so inputs up to the float32 extremes (a range from -3e38 to 3e38)
    normalise without overflow."""

    type = Parameter("range", "how to normalise: range (min..max to 0..1), euclidean (L2 "
                     "norm 1), cityblock (L1 norm 1) or max (divide by the maximum)",
                     options="range/euclidean/cityblock/max")
    INPUT = Input("the values to normalise")
    OUTPUT = Output("the normalised values", size_set="INPUT")

    def init(self):
        self._input = self.INPUT.reshape(self.OUTPUT.shape)
        self._work = np.zeros(self.OUTPUT.shape, dtype=np.float64)
        self._warned = False

    def tick(self):
        with np.errstate(invalid="ignore", over="ignore"):    # NaN and inf are reported
            self._normalize()

    def _normalize(self):
        x = self._input
        offset = 0.0
        if self.type == "range":
            offset = float(x.min())
            divisor = float(x.max()) - offset
        elif self.type == "euclidean":
            divisor = float(np.sqrt(np.sum(np.square(x, dtype=np.float64))))
        elif self.type == "cityblock":
            divisor = float(np.sum(np.abs(x), dtype=np.float64))
        else:  # max
            divisor = float(x.max())
        if divisor == 0.0 or not np.isfinite(divisor):
            if not self._warned:
                self._warned = True
                self.warning(f"cannot normalise ({self.type}): the divisor is {divisor}; "
                             f"the output is 0")
            self.OUTPUT.fill(0)
            return
        np.subtract(x, offset, out=self._work, dtype=np.float64)
        self._work /= divisor
        self.OUTPUT[...] = self._work
