"""StaufferGrimson: adaptive background subtraction with a mixture of Gaussians per pixel."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import as_image, image_shape, is_colour, warn_other_version

IKAROS2_PARAMETERS = ("alpha", "gaussPerPixel", "initialStandardDeviation")
IKAROS3_PARAMETERS = ("learning_rate", "max_gaussians", "initial_variance")


class StaufferGrimson(Module):
    """Adaptive background subtraction with a mixture of Gaussians per pixel (Stauffer and
    Grimson 1999). Each pixel (of each plane of a colour image; a vector is a one-row image)
    has K Gaussians with a weight, a mean and a variance. A value matches a Gaussian when it
    lies within ``threshold`` standard deviations of its mean; of the matching Gaussians the
    one ranked first by weight / standard deviation learns: its mean and variance move
    towards the value and its squared distance at the learning rate, and every weight moves
    towards 1 for it and 0 for the others at that rate. Without a match the Gaussian ranked
    last is replaced by one at the value, with the initial variance and the learning rate as
    its weight. The weights are then scaled to sum 1. Ranked by weight / standard
    deviation, the first Gaussians whose weights add up to more than ``T`` are the
    background, and OUTPUT is 1 where the value matched none of them (foreground; for a
    colour image, in any plane) and 0 elsewhere. The first image starts the model: one
    Gaussian per pixel at its value with weight 1 (the others weight 0), and OUTPUT is 0 on
    that tick. WEIGHTS, MEANS and VARIANCES hold the model, K values per pixel.

    In an Ikaros 2 file the parameters are Ikaros 2's: the learning rate ``alpha``, K =
    ``gaussPerPixel`` and the initial standard deviation ``initialStandardDeviation`` (for
    images of 0..1). In an Ikaros 3 file they are today's Ikaros 3 interface's:
    ``learning_rate``, K = ``max_gaussians`` and ``initial_variance`` (100: for images of
    0..255); the parameters of the other version are not used (a warning when set).

    The reference names the method but neither version's update formulas, so the formulas
    above are this project's reading of the paper. In an Ikaros 2 file the match test cuts
    the fraction off the distance |value - mean| (``match="truncated"``), as C's integer
    abs() does to a float difference: a value matches while it lies less than 1 from the
    mean, and threshold · standard deviation (0.05 at first) only counts once it reaches 1.
    That is this project's reading of Ikaros 2's golden outputs, not a fact from its code:
    on a sine from -1.2 to 1.7, every value less than 1 from the first image (0) stays
    background and every one further away is foreground (the constant cases fit any
    reading). One case cannot tell a cut at 1 from another between 0.77 and 1.04; the cut
    at 1 is taken because Ikaros 2's ChangeDetector takes the same integer absolute value
    of a float difference (its golden outputs show it). So Ikaros 2's module finds no
    foreground in an image of 0..1 unless a pixel moves a whole 1 from its background.
    ``match="exact"`` (the default in an Ikaros 3 file) compares the distance itself, as
    the method does."""

    alpha = Parameter(0.005, "Ikaros 2: the learning rate")
    T = Parameter(0.8, "the part of the weight that is background")
    threshold = Parameter(2.5, "a value matches a Gaussian within this many standard "
                          "deviations")
    gaussPerPixel = Parameter(5, "Ikaros 2: the number of Gaussians per pixel", type="int")
    initialStandardDeviation = Parameter(0.02, "Ikaros 2: the standard deviation of a new "
                                         "Gaussian")
    max_gaussians = Parameter(5, "Ikaros 3: the number of Gaussians per pixel", type="int")
    initial_variance = Parameter(100.0, "Ikaros 3: the variance of a new Gaussian")
    learning_rate = Parameter(0.01, "Ikaros 3: the learning rate")
    match = Parameter("truncated", "truncated: the whole part of |value - mean| is tested, as "
                      "this project reads Ikaros 2 (a defect); exact: |value - mean|",
                      options="truncated/exact", default_v3="exact")
    INPUT = Input("the image: gray (rows, cols), colour (3, rows, cols) or a vector (one "
                  "row)")
    OUTPUT = Output("1 for foreground pixels, 0 for background (rows, cols)")
    WEIGHTS = Output("the weight of each Gaussian: (planes,) rows, cols, K")
    MEANS = Output("the mean of each Gaussian: (planes,) rows, cols, K")
    VARIANCES = Output("the variance of each Gaussian: (planes,) rows, cols, K")

    def configure(self):
        self._v3 = self.dialect == "3"
        self._k = self.max_gaussians if self._v3 else self.gaussPerPixel
        if self._k < 1:
            raise ValueError(f"the number of Gaussians must be at least 1, not {self._k}")

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape:
            shape = image_shape(shape)
            self.set_output_shape("OUTPUT", shape[-2:])
            for name in ("WEIGHTS", "MEANS", "VARIANCES"):
                self.set_output_shape(name, shape + (self._k,))

    def init(self):
        warn_other_version(self, IKAROS2_PARAMETERS, IKAROS3_PARAMETERS)
        image = as_image(self.INPUT)
        self._image = image if is_colour(image.shape) else image[None]
        shape = self._image.shape
        # the model, one contiguous plane per Gaussian (fast to compute on), copied into
        # the outputs (K values per pixel) after each tick
        self._w, self._m, self._v = (np.zeros((self._k,) + shape, np.float32)
                                     for _ in range(3))
        self._views = [(np.moveaxis(out.reshape(shape + (self._k,)), -1, 0), state)
                       for out, state in zip((self.WEIGHTS, self.MEANS, self.VARIANCES),
                                             (self._w, self._m, self._v))]
        self._foreground = np.zeros(shape[1:], bool)
        self._buffers = _Buffers(shape)
        self._started = False

    def _rates(self) -> tuple[float, float]:
        """The learning rate and the variance of a new Gaussian."""
        if self._v3:
            return self.learning_rate, self.initial_variance
        return self.alpha, self.initialStandardDeviation ** 2

    def tick(self):
        rate, variance = self._rates()
        x = self._image
        w, m, v = self._w, self._m, self._v
        if not self._started:
            self._started = True
            w.fill(0.0)
            w[0] = 1.0
            m.fill(0.0)
            m[0] = x
            v.fill(variance)
            self.OUTPUT.fill(0.0)
            self._publish()
            return
        b = self._buffers
        limit = np.float32(self.threshold ** 2)
        truncated = self.match == "truncated"
        rate32, keep = np.float32(rate), np.float32(1.0 - rate)
        # the matching Gaussian ranked first, and the Gaussian ranked last (first on ties)
        b.best_rank.fill(-np.inf)
        b.best.fill(-1)
        b.worst_rank.fill(np.inf)
        b.worst.fill(0)
        for k in range(self._k):
            self._rank(k, b.rank)
            np.subtract(x, m[k], out=b.d2)
            if truncated:
                np.trunc(b.d2, out=b.d2)
            np.square(b.d2, out=b.d2)
            np.multiply(v[k], limit, out=b.t)
            np.less_equal(b.d2, b.t, out=b.match)
            np.greater(b.rank, b.best_rank, out=b.flag)
            b.flag &= b.match
            np.copyto(b.best_rank, b.rank, where=b.flag)
            np.copyto(b.best, k, where=b.flag)
            np.less(b.rank, b.worst_rank, out=b.flag)
            np.copyto(b.worst_rank, b.rank, where=b.flag)
            np.copyto(b.worst, k, where=b.flag)
        np.greater_equal(b.best, 0, out=b.matched)
        np.copyto(b.chosen, b.best)
        np.copyto(b.chosen, b.worst, where=~b.matched)
        b.total.fill(0.0)
        for k in range(self._k):
            wk, mk, vk = w[k], m[k], v[k]
            np.equal(b.chosen, k, out=b.flag)
            wk *= keep
            np.add(wk, rate32, out=wk, where=b.flag)
            b.total += wk
            np.logical_and(b.flag, b.matched, out=b.match)     # learns
            np.subtract(x, mk, out=b.t)
            b.t *= rate32
            np.add(mk, b.t, out=mk, where=b.match)
            np.subtract(x, mk, out=b.d2)
            np.square(b.d2, out=b.d2)
            b.d2 -= vk
            b.d2 *= rate32
            np.add(vk, b.d2, out=vk, where=b.match)
            b.flag &= ~b.matched                                # replaced
            np.copyto(mk, x, where=b.flag)
            np.copyto(vk, np.float32(variance), where=b.flag)
        w /= b.total
        self._classify()
        self._publish()

    def _publish(self):
        """Copy the model into WEIGHTS, MEANS and VARIANCES."""
        for out, state in self._views:
            np.copyto(out, state)

    def _rank(self, k, out):
        """weight / standard deviation of the k-th Gaussians, into ``out``."""
        np.sqrt(self._v[k], out=out)
        np.divide(self._w[k], out, out=out)

    def _classify(self):
        """OUTPUT: 1 where the value matched no background Gaussian: the chosen Gaussian is
        background when the weights ranked above it (by weight / standard deviation, the
        lower index first on ties) add up to at most T."""
        b, w = self._buffers, self._w
        b.best_rank.fill(0.0)
        for k in range(self._k):                    # the rank of the chosen Gaussian
            self._rank(k, b.rank)
            np.equal(b.chosen, k, out=b.flag)
            np.copyto(b.best_rank, b.rank, where=b.flag)
        b.total.fill(0.0)
        for k in range(self._k):
            self._rank(k, b.rank)
            np.greater(b.rank, b.best_rank, out=b.flag)
            np.equal(b.rank, b.best_rank, out=b.match)
            np.less(k, b.chosen, out=b.ahead)
            b.match &= b.ahead
            b.flag |= b.match
            np.add(b.total, w[k], out=b.total, where=b.flag)
        np.less_equal(b.total, np.float32(self.T), out=b.flag)
        b.flag &= b.matched
        np.logical_not(b.flag, out=b.flag)
        np.logical_or.reduce(b.flag, axis=0, out=self._foreground)
        np.copyto(as_image(self.OUTPUT), self._foreground)


class _Buffers:
    """The per-pixel arrays of one tick, made once."""

    def __init__(self, shape):
        for name in ("rank", "best_rank", "worst_rank", "d2", "t", "total"):
            setattr(self, name, np.zeros(shape, np.float32))
        for name in ("best", "worst", "chosen"):
            setattr(self, name, np.zeros(shape, np.int16))
        for name in ("match", "flag", "matched", "ahead"):
            setattr(self, name, np.zeros(shape, bool))
