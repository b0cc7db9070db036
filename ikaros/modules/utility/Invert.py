"""Invert: element-wise reciprocal (Ikaros 3)."""
import numpy as np

from ._functions import ElementFunction


class Invert(ElementFunction):
    """Outputs 1/x of every element of the input, in IEEE arithmetic: 1/0 is inf, 1/-0 is -inf,
    and no error is raised. The output has the shape of the input. New in Ikaros 3."""

    function = staticmethod(np.reciprocal)
