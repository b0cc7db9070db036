"""StaufferGrimson: adaptive background subtraction with a mixture of Gaussians per pixel."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import check_gray


class StaufferGrimson(Module):
    """Adaptive background subtraction (Stauffer and Grimson 1999) for gray images. Each
    pixel has `gaussPerPixel` Gaussians (weight, mean, variance). A value matches a Gaussian
    when it lies within `threshold` standard deviations of its mean; the best-ranked match
    (largest weight / standard deviation) learns the value at rate `alpha` (the common
    simplification ρ = α of the paper's ρ = α·N(x)), every weight moves towards 1 for the
    match and 0 otherwise at rate `alpha`, and without a match the weakest Gaussian is
    replaced by one at the value with standard deviation `initialStandardDeviation` and
    weight `alpha`. A variance never falls below (0.1 · initialStandardDeviation)². Ranked
    by weight / standard deviation, the first Gaussians whose weights add up to more than
    `T` are the background; OUTPUT is 1 where the value matched none of them (foreground)
    and 0 elsewhere. The first image starts the model (all background). The pixels are
    updated together, Gaussian by Gaussian, with NumPy."""

    alpha = Parameter(0.005, "learning rate of the weights, means and variances")
    T = Parameter(0.8, "the part of the weight that is background")
    threshold = Parameter(2.5, "a value matches a Gaussian within this many standard "
                          "deviations")
    gaussPerPixel = Parameter(5, "number of Gaussians per pixel", type="int")
    initialStandardDeviation = Parameter(0.02, "standard deviation of a new Gaussian")
    INPUT = Input("the gray image (rows, cols), values 0..1")
    OUTPUT = Output("1 for foreground pixels, 0 for background", size_set="INPUT")

    def init(self):
        check_gray(self.INPUT.shape)
        if self.gaussPerPixel < 1:
            raise ValueError("gaussPerPixel must be at least 1")
        k, shape = self.gaussPerPixel, self.INPUT.shape
        self._weight = np.zeros((k,) + shape, np.float32)
        self._mean = np.zeros((k,) + shape, np.float32)
        self._var = np.full((k,) + shape, self.initialStandardDeviation ** 2, np.float32)
        self._started = False
        self._rows, self._cols = np.indices(shape)

    def _rank(self):
        """Order of the Gaussians per pixel, best (largest weight / sd) first, (k, ...)."""
        return np.argsort(-self._weight / np.sqrt(self._var), axis=0)

    def tick(self):
        x = self.INPUT
        w, mean, var = self._weight, self._mean, self._var
        if not self._started:
            self._started = True
            mean[0], w[0] = x, 1.0
            self.OUTPUT.fill(0.0)
            return
        a = np.float32(self.alpha)
        order = self._rank()
        r, c = self._rows, self._cols
        ranked_w = w[order, r, c]
        # background: the first Gaussians in rank order whose weights add up past T
        before = np.cumsum(ranked_w, axis=0) - ranked_w
        background_ranked = before < self.T
        d2 = (x - mean) ** 2
        matches = d2 <= (self.threshold ** 2) * var
        ranked_matches = matches[order, r, c]
        any_match = ranked_matches.any(axis=0)
        best_rank = np.argmax(ranked_matches, axis=0)          # first match in rank order
        best = np.take_along_axis(order, best_rank[None], 0)[0]
        is_background = np.take_along_axis(background_ranked, best_rank[None], 0)[0]
        self.OUTPUT[...] = ~(any_match & is_background)
        # learn: weights, then the matched Gaussian's mean and variance
        own = (np.arange(w.shape[0])[:, None, None] == best) & any_match
        w *= 1 - a
        w += a * own
        m = own
        mean[m] += a * (np.broadcast_to(x, mean.shape)[m] - mean[m])
        var[m] += a * (d2[m] - var[m])
        np.maximum(var, (0.1 * self.initialStandardDeviation) ** 2, out=var)
        # no match: the weakest Gaussian starts again at the value
        lost = ~any_match
        if lost.any():
            weakest = order[-1][lost]
            rl, cl = r[lost], c[lost]
            mean[weakest, rl, cl] = x[lost]
            var[weakest, rl, cl] = self.initialStandardDeviation ** 2
            w[weakest, rl, cl] = a
        w /= w.sum(axis=0)
