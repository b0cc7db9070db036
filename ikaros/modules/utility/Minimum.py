"""Minimum: element-wise minimum of two inputs (Ikaros 3)."""
import numpy as np

from ._combine import Combine


class Minimum(Combine):
    """Outputs the smaller of INPUT1 and INPUT2, element by element (Ikaros 3's name for
    Ikaros 2's element-wise Min). NaN as in C++ ``std::min(a, b)``: a NaN in INPUT2 gives
    the INPUT1 value, a NaN in INPUT1 gives NaN. New in Ikaros 3."""

    @staticmethod
    def combine(a, b, out):
        np.copyto(out, np.where(b < a, b, a))
