"""StaufferGrimson: adaptive background subtraction with a mixture of Gaussians per pixel."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import as_image, image_shape, is_colour, warn_here

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
    above are this project's reading of the paper. Ikaros 2's golden outputs agree on
    images that do not change, but not on a changing one: there a value that strays from
    the first image by less than about 0.9 stays background, far beyond threshold ·
    initialStandardDeviation = 0.05, which no reading of the method tried here gives."""

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
        given = getattr(self.element, "attrs", {})
        unused = [p for p in (IKAROS2_PARAMETERS if self._v3 else IKAROS3_PARAMETERS)
                  if p in given]
        if unused:
            warn_here(self, f"{', '.join(unused)}: not used in an Ikaros "
                      f"{'3' if self._v3 else '2'} file (see the class description)")
        image = as_image(self.INPUT)
        self._image = image if is_colour(image.shape) else image[None]
        shape = self._image.shape
        self._w, self._m, self._v = (a.reshape(shape + (self._k,)) for a in (
            self.WEIGHTS, self.MEANS, self.VARIANCES))
        self._foreground = np.zeros(shape, bool)
        self._started = False

    def _rates(self) -> tuple[float, float]:
        """The learning rate and the variance of a new Gaussian."""
        if self._v3:
            return self.learning_rate, self.initial_variance
        return self.alpha, self.initialStandardDeviation ** 2

    def tick(self):
        rate, variance = self._rates()
        x = self._image[..., None]
        w, m, v = self._w, self._m, self._v
        if not self._started:
            self._started = True
            w.fill(0.0)
            w[..., 0] = 1.0
            m[...] = 0.0
            m[..., 0] = self._image
            v.fill(variance)
            self.OUTPUT.fill(0.0)
            return
        rank = w / np.sqrt(v)
        distance2 = np.square(x - m)
        matched = distance2 <= (self.threshold ** 2) * v
        any_match = matched.any(axis=-1)
        # the matching Gaussian ranked first, or else the one ranked last (replaced)
        best = np.where(matched, rank, -np.inf).argmax(axis=-1)
        worst = rank.argmin(axis=-1)
        chosen = np.where(any_match, best, worst)[..., None]
        w *= np.float32(1.0 - rate)
        mc = np.take_along_axis(m, chosen, -1)
        vc = np.take_along_axis(v, chosen, -1)
        learned_m = mc + rate * (x - mc)
        learned_v = vc + rate * (np.square(x - learned_m) - vc)
        hit = any_match[..., None]
        np.put_along_axis(m, chosen, np.where(hit, learned_m, x), -1)
        np.put_along_axis(v, chosen, np.where(hit, learned_v, variance), -1)
        np.put_along_axis(w, chosen, np.take_along_axis(w, chosen, -1) + rate, -1)
        w /= w.sum(axis=-1, keepdims=True)
        self._classify(chosen[..., 0], any_match)

    def _classify(self, chosen, any_match):
        """OUTPUT: 1 where the value matched no background Gaussian."""
        w = self._w
        order = np.argsort(-(w / np.sqrt(self._v)), axis=-1, kind="stable")
        ranked = np.take_along_axis(w, order, -1)
        before = np.cumsum(ranked, axis=-1) - ranked     # weight ranked above each
        background = np.zeros_like(w, dtype=bool)
        np.put_along_axis(background, order, before <= self.T, -1)
        in_background = np.take_along_axis(background, chosen[..., None], -1)[..., 0]
        np.logical_not(any_match & in_background, out=self._foreground)
        np.copyto(as_image(self.OUTPUT), self._foreground.any(axis=0))
