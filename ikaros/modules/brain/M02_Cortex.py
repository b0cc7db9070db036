"""M02_Cortex: a placeholder cortex for Morén's (2002) model of emotional learning."""
from ikaros.module import Input, Module, Output, Parameter


class M02_Cortex(Module):
    """A placeholder cortex for Morén's (2002) model of emotional learning: OUTPUT is a copy of
    INPUT. With ``outputsize`` the output has that many elements instead: the first elements
    of the input are copied and any left over are 0. Ikaros 3 has no such class. The
    golden files of Ikaros 2 have no case of it, as the original refuses their sizes; this
    project's earlier reading of its code, not checked against it, is that it never wrote
    its output, which stayed 0."""

    outputsize = Parameter(None, "number of elements of the output; unset: the size of INPUT",
                           type="int")
    INPUT = Input("the signal")
    OUTPUT = Output("a copy of the input", size_param="outputsize", size_set="INPUT")

    def tick(self):
        out = self.OUTPUT.reshape(-1)
        n = min(out.size, self.INPUT.size)
        out[:n] = self.INPUT.reshape(-1)[:n]
        out[n:] = 0
