"""OneHotVector: a vector that is zero except at one position."""
import math

import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class OneHotVector(Module):
    """Codes an index as a one-hot vector (an Ikaros 3 class): OUTPUT has ``output_size``
    elements, all 0 except the one at the index in INPUT's first element, which is ``value``
    (or VALUE's first element when VALUE is connected). The index is rounded to the nearest
    integer and clamped to 0 ... output_size - 1. An index that is not a number (NaN) gives
    all zeros and a warning (once, until the index is a number again). ``output_size`` below
    1 is an error."""

    output_size = Parameter(1, "number of elements of the output", type="int",
                            range=(1, None))
    value = Parameter(1.0, "the value at the index (when VALUE is not connected)")
    INPUT = Input("the index (its first element)")
    VALUE = Input("the value at the index (its first element); optional", optional=True)
    OUTPUT = Output("zeros with the value at the index", size_param="output_size")

    def init(self):
        self._warned = False

    def tick(self):
        self.OUTPUT[...] = 0
        index = float(self.INPUT.flat[0]) if self.INPUT.size else math.nan
        if math.isnan(index):
            if not self._warned:
                self.warning("the index is not a number; the output is all zeros")
                self._warned = True
            return
        self._warned = False
        position = int(np.clip(np.rint(index), 0, self.OUTPUT.size - 1))
        self.OUTPUT[position] = self.VALUE.flat[0] if self.VALUE is not None and \
            self.VALUE.size else self.value
