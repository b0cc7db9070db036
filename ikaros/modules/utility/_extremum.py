"""A base for Max and Min: element-wise over INPUT1 and INPUT2 (Ikaros 2) or a reduction of
INPUT to one value (Ikaros 3)."""
import numpy as np

from ikaros.module import Module

from ._elementwise import _as_shape


class Extremum(Module):
    """The interface is chosen by what is connected: INPUT1 and INPUT2 (Ikaros 2's Max and
    Min, element-wise) or INPUT (Ikaros 3's, one value). The two are disjoint, so every file
    of either version reads as written whatever its dialect; connecting both, or neither,
    is an error naming the module."""

    reduce = None       # np.nanmax or np.nanmin: the Ikaros 3 reduction
    pairwise = None     # np.maximum or np.minimum: the Ikaros 2 element-wise operation

    def set_sizes(self):
        pair = self.connected("INPUT1") or self.connected("INPUT2")
        if pair and self.connected("INPUT"):
            raise ValueError("connect either INPUT (Ikaros 3: one value over all elements) or "
                             "INPUT1 and INPUT2 (Ikaros 2: element by element), not both")
        if self.connected("INPUT"):
            self.set_output_shape("OUTPUT", 1)
            return
        if not (self.connected("INPUT1") and self.connected("INPUT2")):
            raise ValueError("INPUT1 and INPUT2 must both be connected (Ikaros 2), or INPUT "
                             "alone (Ikaros 3)")
        a, b = self.input_shape("INPUT1"), self.input_shape("INPUT2")
        if a is None or b is None:
            return
        if int(np.prod(a)) != int(np.prod(b)):
            raise ValueError(f"INPUT1 and INPUT2 must have the same size; INPUT1 has shape "
                             f"{a}, INPUT2 {b}")
        self.set_output_shape("OUTPUT", a)

    def init(self):
        self._reduction = self.INPUT is not None
        if self._reduction:
            if self.INPUT.size == 0:
                self.fatal_error("the input is empty: an empty matrix has no "
                                 f"{type(self).__name__.lower()}")
            return
        shape = self.OUTPUT.shape
        self._a, self._b = _as_shape(self.INPUT1, shape), _as_shape(self.INPUT2, shape)

    def tick(self):
        if self._reduction:
            value = type(self).reduce(self.INPUT)
            # all NaN: Ikaros 3 skips NaNs and gives the starting value (-inf for Max)
            self.OUTPUT[0] = self._empty_value if np.isnan(value) else value
        else:
            type(self).pairwise(self._a, self._b, out=self.OUTPUT)
