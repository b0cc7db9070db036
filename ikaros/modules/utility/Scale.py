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

    # many instances run as one NumPy operation (see ikaros/kernel/fusion.py)
    elementwise = [("multiply", "INPUT", "@factor"), ("multiply", "INPUT", "@factor", "SCALE[0]")]
    compiled_op = "scale"   # an instruction of the compiled tick (ikaros/kernel/compiled/)

    def init(self):
        self._scale = None if self.SCALE is None else self.SCALE.reshape(-1)[:1]

    def tick(self):
        np.multiply(self.INPUT, self.factor, out=self.OUTPUT)
        if self._scale is not None:
            np.multiply(self.OUTPUT, self._scale, out=self.OUTPUT)
