"""M02_OFC: the orbitofrontal cortex of Morén's (2002) model of emotional learning."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class M02_OFC(Module):
    """The orbitofrontal cortex of Morén's (2002) amygdala-orbitofrontal model of emotional
    learning. It learns to inhibit the amygdala when its prediction exceeds the reward. Its
    units stand for stimulus-context pairs: T = the outer product of CON and the stimulus
    INPUT (T[j + n*i] = INPUT[j] * CON[i]; just INPUT when CON is unconnected), each with a
    weight W in 0..1 (starting at 0) and an activity O = T * W. The inhibition it sends the
    amygdala is EO = sum O. Learning pairs the previous tick's T with the amygdala's
    prediction sum A (connect M02_Amygdala.A with delay 1, so it belongs to that tick) and
    this tick's reward: the reinforcement is R = max(0, sum A - Rew) - sum O(t-1) when Rew is
    not 0, and max(0, sum A - sum O(t-1)) when it is, and W += beta * T(t-1) * R, clipped to
    0..1. So omitted rewards build inhibition (extinction) and rewards remove it. Rew's first
    element is used."""

    beta = Parameter(0.2, "learning rate")
    INPUT = Input("the conditioned stimuli (from the sensory cortex)", flatten=True)
    A = Input("the amygdala's node activities (connect with delay 1)", flatten=True)
    CON = Input("the context (from M02_Hippocampus)", optional=True, flatten=True)
    Rew = Input("the reward (unconditioned stimulus); its first element is used", flatten=True)
    EO = Output("the inhibition of the amygdala", size="1")
    W = Output("the weights of the stimulus-context units")

    def set_sizes(self):
        s, c = self.input_shape("INPUT"), self.input_shape("CON")
        if s is None or c is None:
            return
        n_s = int(np.prod(s)) if s else 0
        n_c = int(np.prod(c)) if c else 1
        self.set_output_shape("W", n_s * n_c)

    def init(self):
        n = self.W.size
        self._w = np.zeros(n)
        self._t_last = np.zeros(n)
        self._sum_o_last = 0.0
        self.W[...] = 0
        self.EO[...] = 0

    def tick(self):
        s = self.INPUT.astype(np.float64)
        t = np.outer(self.CON, s).ravel() if self.CON is not None else s
        sum_a = float(self.A.sum())
        rew = float(self.Rew[0]) if self.Rew.size else 0.0
        if rew != 0.0:
            r = max(0.0, sum_a - rew) - self._sum_o_last
        else:
            r = max(0.0, sum_a - self._sum_o_last)
        self._w += self.beta * self._t_last * r
        np.clip(self._w, 0.0, 1.0, out=self._w)
        o = t * self._w
        self._sum_o_last = float(o.sum())
        self._t_last = t
        self.W[...] = self._w
        self.EO[0] = self._sum_o_last
