"""Delta: conditioning with the delta rule (acquisition only)."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Delta(Module):
    """A simple conditioning model that learns with the delta rule, acquisition only. On every
    tick the prediction is CR = sum(CS * w) (a linear output with no bias and no clipping);
    then, when the error e = sum(US) - CR is positive, every weight grows by
    alpha * CS[i] * e. The weights start at zero and never shrink, so the module learns the
    strength of each stimulus alone (or any map whose inputs do not overlap) but not
    extinction. CS may have any shape (it is read flat); all elements of US are summed. While
    CS or US is unconnected nothing is learned and CR is 0. In an Ikaros 3 file ``inverse``
    reverses the error's sign (e = CR - sum(US)), so the weights grow only while the
    prediction exceeds the US: the reference does not describe ``inverse``; this is the
    simplest rule that gives what Ikaros 3 computed on its one recorded case (CS 1, US 0.5,
    inverse: CR stays 0). An Ikaros 2 file ignores ``inverse``: with it the Ikaros 2 class
    learned towards the US exactly as without it (the golden files show it). ``beta``, ``gamma``, ``delta`` and ``epsilon`` are unused (for beta and gamma the
    golden files show Ikaros 2 ignoring them);
    they are kept so models that set them load unchanged. ``output="error"`` (this
    project's addition) outputs the prediction error sum(US) - CR instead of the
    prediction: the US signal once the learned response has inhibited it, as in the
    cerebellum. The command ``reset`` sets the weights to zero; the weights are state, kept
    by save, load and reset of the state (as ``weights``)."""

    state = ("weights",)

    alpha = Parameter(0.1, "the learning rate")
    beta = Parameter(1.0, "unused (kept for Ikaros 2 models)")
    gamma = Parameter(1.0, "unused (kept for Ikaros 2 models)")
    delta = Parameter(1.0, "unused (kept for Ikaros 2 models)")
    epsilon = Parameter(1.0, "unused (kept for Ikaros 2 models)")
    inverse = Parameter(False, "Ikaros 3 files: reverse the error's sign, learning only "
                        "while CR exceeds sum(US) (Ikaros 2 ignores it; see the description)")
    output = Parameter("prediction", "prediction: CR = sum(CS * w) (the original); error: the "
                       "prediction error sum(US) - CR, as the cerebellum's learned response "
                       "inhibits the US pathway", options="prediction/error")
    CS = Input("the conditioned stimulus: one element per stimulus", optional=True)
    US = Input("the unconditioned stimulus; its elements are summed into the target",
               optional=True)
    CR = Output("the conditioned response, sum(CS * w), or the prediction error with "
                "output=error",
                size="1")

    def init(self):
        n = 0 if self.CS is None else self.CS.size
        self.weights = np.zeros(n, np.float32)   # the learned association of each CS element
        self.CR[...] = 0

    def command(self, name, x=0, y=0, value=None):
        if name == "reset":
            self.weights[...] = 0

    def tick(self):
        if self.CS is None or self.US is None:
            self.CR[...] = 0
            return
        cs = self.CS.reshape(-1)
        target = np.float32(np.sum(self.US, dtype=np.float64))
        prediction = np.float32(np.dot(cs, self.weights))
        error = target - prediction
        if self.inverse and self.dialect == "3":
            error = -error
        if error > 0:
            self.weights += np.float32(self.alpha) * error * cs
        self.CR[0] = target - prediction if self.output == "error" else prediction
