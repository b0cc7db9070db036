"""Maximum: element-wise maximum of two inputs (Ikaros 3)."""
import numpy as np

from ._combine import Combine


class Maximum(Combine):
    """Outputs the larger of INPUT1 and INPUT2, element by element (Ikaros 3's name for
    Ikaros 2's element-wise Max). NaN as in C++ ``std::max(a, b)``: a NaN in INPUT2 gives
    the INPUT1 value, a NaN in INPUT1 gives NaN. New in Ikaros 3."""

    @staticmethod
    def combine(a, b, out):
        np.copyto(out, np.where(a < b, b, a))
