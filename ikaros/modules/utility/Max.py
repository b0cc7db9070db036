"""Max: element-wise maximum of two inputs (Ikaros 2), or the largest element of one
input (Ikaros 3)."""
import warnings

import numpy as np

from ikaros.module import Input, Output

from ._extremum import Extremum


def _nanmax(x):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)     # all NaN
        return np.nanmax(x)


class Max(Extremum):
    """Ikaros 2: outputs the element-wise maximum of INPUT1 and INPUT2 (same number of
    elements; the output has their shape). Ikaros 3: outputs the largest element of INPUT
    (one value; NaNs are skipped, an all-NaN input gives -inf, an empty one is an error);
    Ikaros 3's element-wise class is Maximum/Minimum. The version is chosen by what is
    connected (INPUT, or INPUT1 and INPUT2), so a file of either version works whatever its
    dialect."""

    INPUT = Input("Ikaros 3: the values to reduce, of any shape", optional=True)
    INPUT1 = Input("Ikaros 2: the first input", optional=True)
    INPUT2 = Input("Ikaros 2: the second input", optional=True)
    OUTPUT = Output("Ikaros 2: the larger of the two inputs, element by element; Ikaros 3: "
                    "the largest element of INPUT (one value)")

    compiled_op = "maximum"   # an instruction of the compiled tick (Ikaros 2 interface)
    reduce = staticmethod(_nanmax)
    pairwise = staticmethod(np.maximum)
    _empty_value = np.float32("-inf")
