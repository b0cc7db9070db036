"""Or: element-wise logical or (Ikaros 3)."""
import numpy as np

from ._combine import Combine


class Or(Combine):
    """Outputs 1 where INPUT1 or INPUT2 (or both) is non-zero (any non-zero value, a
    negative one or NaN included, counts as true) and 0 elsewhere. New in Ikaros 3."""

    @staticmethod
    def combine(a, b, out):
        np.logical_or(a, b, out=out, casting="unsafe")
