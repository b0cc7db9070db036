"""Xor: logical exclusive or of two inputs (Ikaros 2: of their first elements; Ikaros 3:
element by element)."""
import numpy as np

from ikaros.module import Parameter

from ._logic import Logic


class Xor(Logic):
    """The combination is true when exactly one of INPUT1 and INPUT2 is true. In an Ikaros
    2 file the class is scalar (Ikaros 2's): OUTPUT is ``high`` or ``low`` (one element)
    and INVERSE the other. INPUT1's first element is true when above ``threshold``, but
    INPUT2's when above 0, whatever the threshold: a defect of Ikaros 2 that the golden
    files show (0.3 and 0.05 with threshold 0.1, or 1.2 and 0.24 with the default 0.5,
    give ``low``), kept as the default; ``input2_threshold="threshold"`` (this project's)
    compares INPUT2 with the threshold too. In an Ikaros 3 file it is Ikaros 3's
    element-wise class: OUTPUT is 1 where exactly one of the two elements is non-zero (a
    negative value or NaN counts as non-zero), else 0; INPUT1 and INPUT2 must have the
    same shape."""

    operation = staticmethod(np.logical_xor)

    input2_threshold = Parameter("zero", "Ikaros 2: what INPUT2 is compared with: zero (the "
                                 "original's defect) or threshold", options="zero/threshold")

    def threshold_2(self) -> float:
        return self.threshold if self.input2_threshold == "threshold" else 0.0
