"""Scale: multiplies a signal by a factor."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Scale(Module):
    """Multiplies the input by ``factor``, and by the first element of SCALE when that input
    is connected."""

    factor = Parameter(1.0, "the factor the input is multiplied by")
    INPUT = Input("the signal to scale")
    SCALE = Input("an extra factor: its first element multiplies the output", optional=True)
    OUTPUT = Output("the scaled signal", size_set="INPUT")

    def tick(self):
        if self.SCALE is None:
            np.multiply(self.INPUT, self.factor, out=self.OUTPUT)
        else:
            np.multiply(self.INPUT, self.factor * float(self.SCALE.flat[0]), out=self.OUTPUT)
