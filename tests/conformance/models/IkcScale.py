"""Code for the IkcScale class; its parameters and ports are declared in IkcScale.ikc."""
import numpy as np

from ikaros.module import Module


class IkcScale(Module):
    def tick(self):
        np.multiply(self.INPUT, self.gain, out=self.OUTPUT)
        self.DOUBLE[...] = self.gain
