"""M02_SensoryCortex: the sensory cortex of Morén's (2002) model of emotional learning."""
from ikaros.module import Input, Module, Output


class M02_SensoryCortex(Module):
    """The naive sensory cortex of Morén's (2002) amygdala-orbitofrontal model of emotional
    learning: it passes the stimuli from the thalamus on unchanged, to the amygdala and the
    orbitofrontal cortex."""

    INPUT = Input("the stimuli from the thalamus")
    OUTPUT = Output("a copy of the stimuli", size_set="INPUT")

    def tick(self):
        self.OUTPUT[...] = self.INPUT
