"""Clip: element-wise clamp between two limits (Ikaros 3)."""
import numpy as np

from ikaros.module import Parameter

from ._functions import ElementFunction


class Clip(ElementFunction):
    """Clamps every element of the input to the range between ``a`` and ``b``. The limits
    may be given in either order (as in Ikaros 3, a > b clamps to [b, a]). The output has
    the shape of the input. New in Ikaros 3."""

    a = Parameter(0.0, "one limit (the lower one when a <= b)")
    b = Parameter(1.0, "the other limit (the upper one when a <= b)")

    def tick(self):
        np.clip(self.INPUT, min(self.a, self.b), max(self.a, self.b), out=self.OUTPUT)
