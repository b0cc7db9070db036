"""OneHotVector: a vector that is zero except at one position."""
import math

from ikaros.module import Input, Module, Output, Parameter


class OneHotVector(Module):
    """Codes an index as a one-hot vector: OUTPUT has ``output_size`` elements, all 0 except
    the one at the index in INPUT (one element), which is ``value`` (or VALUE's first element
    when VALUE is connected). As in Ikaros 3 (``index="truncate"``, the default; facts found
    by running the original) only an index of exactly -1 gives all zeros; any other index is
    truncated toward zero (2.6 gives 2) and clipped into 0 ... output_size - 1 (-0.5 and -2
    mark the first element, an index past the end the last). Ikaros 2 gives the same for
    the indices its golden files show (whole ones inside the output); for the others this
    is this project's reading, taken from Ikaros 3. ``index="round"`` (this project's
    variant) rounds to the nearest integer and clamps into 0 ... output_size - 1, so -1
    marks the first element too. An index that is not a number (NaN) gives all zeros and a
    warning (once, until the index is a number again). An INPUT of more than one element
    gives all zeros in an Ikaros 2 file, as Ikaros 2 does (golden files), with a warning,
    and is refused in an Ikaros 3 file, as Ikaros 3 refuses it; ``output_size`` below 1 is
    an error."""

    output_size = Parameter(10, "number of elements of the output", type="int",
                            range=(1, None))
    value = Parameter(1.0, "the value at the index (when VALUE is not connected)")
    index = Parameter("truncate", "how a fractional or out-of-range index is taken: "
                      "truncate (Ikaros 3: -1 gives all zeros, others truncated and clipped "
                      "into the output) or round (nearest, clamped into the output)",
                      options="truncate/round")
    INPUT = Input("the index (one element)")
    VALUE = Input("the value at the index (its first element); optional", optional=True)
    OUTPUT = Output("zeros with the value at the index", size_param="output_size")

    def init(self):
        self._warned = False
        self._several = self.INPUT.size != 1
        if self._several and self.dialect == "3":
            self.fatal_error(f"INPUT must have one element (the index), not "
                             f"{self.INPUT.size}")
        elif self._several:
            self.warning(f"INPUT has {self.INPUT.size} elements, not one index: the output "
                         f"is all zeros, as in Ikaros 2")

    def _position(self, index: float):
        """The element to mark, or None for all zeros."""
        last = self.OUTPUT.size - 1
        if self.index == "round":
            return int(min(max(round(index) if math.isfinite(index) else index, 0), last))
        if index == -1:
            return None
        return int(min(max(math.trunc(index) if math.isfinite(index) else index, 0), last))

    def tick(self):
        self.OUTPUT[...] = 0
        if self._several:
            return
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
