"""OneHotVector: a vector that is zero except at one position."""
import math

from ikaros.module import Input, Module, Output, Parameter


class OneHotVector(Module):
    """Codes an index as a one-hot vector (an Ikaros 3 class): OUTPUT has ``output_size``
    elements, all 0 except the one at the index in INPUT (one element), which is ``value``
    (or VALUE's first element when VALUE is connected). As in Ikaros 3 (``index="truncate"``,
    the default) a fractional index is truncated (2.6 gives 2), a negative index gives all
    zeros and an index past the end marks the last element. ``index="round"`` (this project's
    variant) rounds to the nearest integer and clamps into 0 ... output_size - 1, so a
    negative index marks the first element. An index that is not a number (NaN) gives all
    zeros and a warning (once, until the index is a number again). An INPUT of more than one
    element is refused, as Ikaros 3 refuses it; ``output_size`` below 1 is an error."""

    output_size = Parameter(10, "number of elements of the output", type="int",
                            range=(1, None))
    value = Parameter(1.0, "the value at the index (when VALUE is not connected)")
    index = Parameter("truncate", "how a fractional or out-of-range index is taken: "
                      "truncate (Ikaros 3: negative gives all zeros) or round (nearest, "
                      "clamped into the output)", options="truncate/round")
    INPUT = Input("the index (one element)")
    VALUE = Input("the value at the index (its first element); optional", optional=True)
    OUTPUT = Output("zeros with the value at the index", size_param="output_size")

    def init(self):
        self._warned = False
        if self.INPUT.size != 1:
            self.fatal_error(f"INPUT must have one element (the index), not "
                             f"{self.INPUT.size}")

    def _position(self, index: float):
        """The element to mark, or None for all zeros."""
        last = self.OUTPUT.size - 1
        if self.index == "round":
            return int(min(max(round(index) if math.isfinite(index) else index, 0), last))
        if index < 0:
            return None
        return last if index >= last else int(index)

    def tick(self):
        self.OUTPUT[...] = 0
        index = float(self.INPUT.flat[0]) if self.INPUT.size else math.nan
        if math.isnan(index):
            if not self._warned:
                self.warning("the index is not a number; the output is all zeros")
                self._warned = True
            return
        self._warned = False
        position = self._position(index)
        if position is not None:
            self.OUTPUT[position] = self.VALUE.flat[0] if self.VALUE is not None and \
                self.VALUE.size else self.value
