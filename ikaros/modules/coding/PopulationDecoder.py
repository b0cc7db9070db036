"""PopulationDecoder: values and amplitudes from Gaussian population codes."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class PopulationDecoder(Module):
    """Decodes population codes such as PopulationCoder makes, one per row of INPUT (a 1-D
    input is one row), as Ikaros 2 does (the class is not in Ikaros 3). Unit k of a row of n
    units stands for min + k (max - min) / (n - 1). OUTPUT is the mean of these values
    weighted by the row's activity, sum(x_k v_k) / sum(x_k) (negative activities count with
    their sign; that a row of negative sum is decoded by the same formula is this project's
    reading); a row whose activity sums to 0 decodes to the middle of the range. AMPLITUDE
    is the sum of the absolute values of the row. These are Ikaros 2's formulas, as the
    golden files show; sigma has no part in them.

    ``amplitude="fit"`` (this project's) gives instead the height of the Gaussian of width
    ``sigma`` (in units) centred on the decoded value that best fits the row (least
    squares), so that decoding an unnormalized PopulationCoder code gives back its
    AMPLITUDE; with sigma 0 that is the activity of the unit nearest the decoded value."""

    sigma = Parameter(1.0, "the width (standard deviation) of the tuning curves, in units "
                      "(used only by amplitude=\"fit\")")
    min = Parameter(0.0, "the value the first unit stands for")
    max = Parameter(1.0, "the value the last unit stands for")
    amplitude = Parameter("sum", "sum: AMPLITUDE is the sum of the row's absolute values "
                          "(Ikaros 2); fit: the height of the best-fitting Gaussian",
                          options="sum/fit")
    INPUT = Input("the population codes, one per row")
    OUTPUT = Output("the decoded value of each row", shape="INPUT.rows")
    AMPLITUDE = Output("the amplitude of each row's code", shape="INPUT.rows")

    def init(self):
        x = self.INPUT
        self._x = x.reshape(1, -1) if x.ndim < 2 else x.reshape(-1, x.shape[-1])
        n = self._x.shape[1]
        self._units = np.arange(n, dtype=np.float64)[None, :]
        self._fractions = self._units / (n - 1) if n > 1 else np.full((1, 1), 0.5)

    def tick(self):
        x = self._x.astype(np.float64)
        values = self.min + (self.max - self.min) * self._fractions
        weight = x.sum(axis=1)
        middle = self.min + (self.max - self.min) / 2
        safe = np.where(weight != 0, weight, 1.0)
        decoded = np.where(weight != 0, (x * values).sum(axis=1) / safe, middle)
        self.OUTPUT[...] = decoded
        if self.amplitude == "sum":
            self.AMPLITUDE[...] = np.abs(x).sum(axis=1)
        else:
            self.AMPLITUDE[...] = self._fitted_height(x, decoded)

    def _fitted_height(self, x, decoded):
        """The height of the Gaussian of width sigma at the decoded value that best fits each
        row (least squares)."""
        n = x.shape[1]
        # the decoded value's position in units (the middle unit when max equals min)
        if n > 1 and self.max != self.min:
            c = (n - 1) * (decoded - self.min) / (self.max - self.min)
        else:
            c = np.full(decoded.shape, (n - 1) / 2)
        c = c.reshape(-1, 1)
        if self.sigma > 0:
            g = np.exp(-(self._units - c) ** 2 / (2 * self.sigma ** 2))
            g2 = (g * g).sum(axis=1)
            return np.where(g2 > 0, (x * g).sum(axis=1) / np.where(g2 > 0, g2, 1), 0.0)
        nearest = np.clip(np.floor(c + 0.5), 0, n - 1).astype(np.int64)
        return np.take_along_axis(x, nearest, axis=1)[:, 0]
