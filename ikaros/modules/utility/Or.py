"""Or: logical or of two inputs (Ikaros 2: of their first elements; Ikaros 3: element by
element)."""
import numpy as np

from ._logic import Logic


class Or(Logic):
    """The combination is true when INPUT1 or INPUT2 (or both) is true. In an Ikaros 2 file
    the class is scalar (Ikaros 2's): the inputs' first elements are true when above
    ``threshold``; OUTPUT is ``high`` or ``low`` (one element) and INVERSE the other.
    In an Ikaros 3 file it is Ikaros 3's element-wise class: OUTPUT is 1 where either
    element (or both) is non-zero (a negative value or NaN counts as non-zero), else 0;
    INPUT1 and INPUT2 must have the same shape."""

    operation = staticmethod(np.logical_or)
