"""M02_Amygdala: the amygdala of Morén's (2002) model of emotional learning."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class M02_Amygdala(Module):
    """The amygdala of Morén's (2002) amygdala-orbitofrontal model of emotional learning, as
    Ikaros 2 computes it (Ikaros 3 has no such class). Each stimulus element S_i (INPUT) has
    a plastic weight V_i (starting at 0) and a node A_i = S_i * V_i. Learning pairs the
    stimulus of the previous tick with the reward of this one: V_i += alpha * S_i(t-1) *
    max(0, Rew(t) - sum A(t-1)), so a weight moves only in the direction of its stimulus
    (it grows for a positive one; extinction is the orbitofrontal cortex's inhibition).
    The emotional output is E = clip(sum A - EO, 0, 1), where EO is the inhibition from
    M02_OFC (0 when unconnected). With ``response`` = ``delayed`` (Ikaros 2) E lags: E(t) =
    clip(sum A(t-2) - EO(t-1), 0, 1), two ticks behind the nodes A; ``immediate`` gives the
    E of the same tick. Rew and EO: their first elements are used. A and V have the shape of
    INPUT. The golden files of Ikaros 2 show all of this; they do not show whether Ikaros 2
    bounds V (no case makes a weight reach 1), and this project does not bound it, as the
    class's formula has no bound."""

    alpha = Parameter(0.2, "learning rate")
    response = Parameter("delayed", "delayed: E(t) from sum A(t-2) and EO(t-1), as Ikaros 2; "
                         "immediate: E from sum A and EO of the same tick",
                         options="delayed/immediate")
    INPUT = Input("the conditioned stimuli (from the sensory cortex and thalamus)")
    EO = Input("inhibition from the orbitofrontal cortex; its first element is used",
               optional=True, flatten=True)
    Rew = Input("the reward (unconditioned stimulus); its first element is used", flatten=True)
    A = Output("the activity of the stimulus nodes, S * V; goes to the orbitofrontal cortex",
               size_set="INPUT")
    E = Output("the emotional output: the conditioned response", size="1")
    V = Output("the plastic weights, for display", size_set="INPUT")

    def init(self):
        self._v = np.zeros(self.INPUT.size)
        self._s_last = np.zeros(self.INPUT.size)
        self._sum_a_last = 0.0
        self._e_next = 0.0
        for out in (self.A, self.E, self.V):
            out[...] = 0

    def tick(self):
        s = self.INPUT.reshape(-1).astype(np.float64)
        rew = float(self.Rew[0]) if self.Rew.size else 0.0
        self._v += self.alpha * self._s_last * max(0.0, rew - self._sum_a_last)
        a = s * self._v
        sum_a = float(a.sum())
        eo = float(self.EO[0]) if self.EO is not None and self.EO.size else 0.0
        self.A.reshape(-1)[...] = a
        self.V.reshape(-1)[...] = self._v
        if self.response == "delayed":
            self.E[0] = self._e_next
            self._e_next = min(max(self._sum_a_last - eo, 0.0), 1.0)
        else:
            self.E[0] = min(max(sum_a - eo, 0.0), 1.0)
        self._s_last = s
        self._sum_a_last = sum_a
