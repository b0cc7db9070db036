"""Negate: element-wise negation (Ikaros 3)."""
import numpy as np

from ._functions import ElementFunction


class Negate(ElementFunction):
    """Outputs minus every element of the input. The output has the shape of the input. New in
    Ikaros 3."""

    function = staticmethod(np.negative)
