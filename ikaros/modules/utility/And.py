"""And: element-wise logical and (Ikaros 3)."""
import numpy as np

from ._combine import Combine


class And(Combine):
    """Outputs 1 where both INPUT1 and INPUT2 are non-zero (any non-zero value, a negative
    one or NaN included, counts as true) and 0 elsewhere. New in Ikaros 3."""

    @staticmethod
    def combine(a, b, out):
        np.logical_and(a, b, out=out, casting="unsafe")
