"""Not: element-wise logical not (Ikaros 3)."""
import numpy as np

from ._functions import ElementFunction


def _logical_not(x, out):
    np.equal(x, 0, out=out, casting="unsafe")


class Not(ElementFunction):
    """Outputs 1 where the input is 0 (-0 included) and 0 elsewhere (NaN gives 0). The
    output has the shape of the input. New in Ikaros 3."""

    function = staticmethod(_logical_not)
