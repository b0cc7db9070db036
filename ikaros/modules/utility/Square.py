"""Square: element-wise square (Ikaros 3)."""
import numpy as np

from ._functions import ElementFunction


class Square(ElementFunction):
    """Outputs the square x·x of every element of the input. The output has the shape of the
    input. New in Ikaros 3."""

    function = staticmethod(np.square)
