"""Exp: element-wise exponential (Ikaros 3)."""
import numpy as np

from ._functions import ElementFunction


class Exp(ElementFunction):
    """Outputs e to the power of every element of the input (float32: above about 88.7 it
    overflows to inf). The output has the shape of the input. New in Ikaros 3."""

    function = staticmethod(np.exp)
