"""Xor: element-wise logical exclusive or (Ikaros 3)."""
import numpy as np

from ._combine import Combine


class Xor(Combine):
    """Outputs 1 where exactly one of INPUT1 and INPUT2 is non-zero (any non-zero value, a
    negative one or NaN included, counts as true) and 0 elsewhere. New in Ikaros 3."""

    @staticmethod
    def combine(a, b, out):
        np.logical_xor(a, b, out=out, casting="unsafe")
