"""M02_Thalamus: the thalamus of Morén's (2002) model of emotional learning."""
from ikaros.module import Input, Module, Output


class M02_Thalamus(Module):
    """The thalamus of Morén's (2002) amygdala-orbitofrontal model of emotional learning: it
    passes the stimulus INPUT on to OUTPUT (towards the sensory cortex) and outputs TH, the
    largest element of the input, a non-specific signal that some stimulus is present, which
    goes directly to the amygdala."""

    INPUT = Input("the stimuli")
    OUTPUT = Output("a copy of the stimuli", size_set="INPUT")
    TH = Output("the largest stimulus (0 for an empty input)", size="1")

    def tick(self):
        self.OUTPUT[...] = self.INPUT
        self.TH[0] = self.INPUT.max() if self.INPUT.size else 0.0
