"""StaufferGrimson: adaptive background subtraction with a mixture of Gaussians per pixel."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._cv import check_gray, opencv


class StaufferGrimson(Module):
    """Adaptive background subtraction with a mixture of `gaussPerPixel` Gaussians per pixel
    (Stauffer and Grimson 1999), for gray images. A value matches a Gaussian when it lies
    within `threshold` standard deviations of its mean; matched Gaussians learn the value
    and every weight moves towards 1 for the match and 0 otherwise at rate `alpha`; without
    a match the weakest Gaussian is replaced by one at the value with standard deviation
    `initialStandardDeviation`. Ranked by weight / standard deviation, the first Gaussians
    whose weights add up to more than `T` are the background, and OUTPUT is 1 where the
    value matched none of them (foreground) and 0 elsewhere. The model is OpenCV's
    BackgroundSubtractorMOG2 with its complexity reduction turned off, which is this model
    with Zivkovic's refinement of the update (a matched Gaussian learns at alpha / weight
    rather than at α·N(x)); standard deviations never fall below a tenth of
    initialStandardDeviation. The first image starts the model, and OUTPUT is 0 on that
    tick. (The reference names Stauffer and Grimson's method but not Ikaros 2's update
    formulas, so whether its values follow the paper's α·N(x) or this refinement is not
    known.)"""

    alpha = Parameter(0.005, "learning rate of the weights, means and variances")
    T = Parameter(0.8, "the part of the weight that is background")
    threshold = Parameter(2.5, "a value matches a Gaussian within this many standard "
                          "deviations")
    gaussPerPixel = Parameter(5, "number of Gaussians per pixel", type="int")
    initialStandardDeviation = Parameter(0.02, "standard deviation of a new Gaussian")
    INPUT = Input("the gray image (rows, cols), values 0..1")
    OUTPUT = Output("1 for foreground pixels, 0 for background", size_set="INPUT")

    def configure(self):
        self.cv2 = opencv()

    def init(self):
        check_gray(self.INPUT.shape)
        if self.gaussPerPixel < 1:
            raise ValueError("gaussPerPixel must be at least 1")
        self._model = self.cv2.createBackgroundSubtractorMOG2(detectShadows=False)
        self._model.setComplexityReductionThreshold(0.0)
        self._mask = np.zeros(self.INPUT.shape, np.uint8)
        self._started = False

    def tick(self):
        model, sd = self._model, self.initialStandardDeviation
        model.setNMixtures(self.gaussPerPixel)
        model.setBackgroundRatio(self.T)
        model.setVarThreshold(self.threshold ** 2)
        model.setVarInit(sd ** 2)
        model.setVarMin((0.1 * sd) ** 2)
        model.setVarMax(max(1.0, 4 * sd ** 2))
        if not self._started:                     # the first image starts the model
            self._started = True
            model.apply(self.INPUT, self._mask, 1.0)
            self.OUTPUT.fill(0.0)
            return
        model.apply(self.INPUT, self._mask, self.alpha)
        np.multiply(self._mask, np.float32(1 / 255), out=self.OUTPUT, casting="unsafe")
