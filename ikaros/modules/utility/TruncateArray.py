"""TruncateArray: picks chosen elements of an array."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class TruncateArray(Module):
    """Outputs the input elements chosen by ``selection``, a list of positions counted from
    1: selection="4 6" outputs the 4th and 6th elements. As in Ikaros 2 (golden files) the
    selection is taken from the start of the whole input whatever ``array_length`` and
    ``loop`` say, and a position outside the input gives 0 (position 0 does in the
    original; past the end it would read outside the input), with a warning.
    ``honour_loop="yes"`` (this project's) makes ``loop`` work: the input is read as
    consecutive arrays of ``array_length`` elements and the selection is taken from each of
    them; when the input holds more than one whole array the output is a matrix with one
    row per array (elements after the last whole array are ignored). A position that is
    not a whole number, or an empty selection, is an error at start-up."""

    array_length = Parameter(16, "the length of each array in the input when loop is on "
                             "(with honour_loop)", type="int")
    loop = Parameter(True, "take the selection from every array of array_length elements "
                     "(with honour_loop; Ikaros 2 declares it but does not use it)")
    honour_loop = Parameter(False, "this project's: loop works as described (Ikaros 2 takes "
                            "the selection from the start of the input only)")
    selection = Parameter("", "the positions to output, counted from 1", type="array")
    INPUT = Input("the array to pick elements from", flatten=True)
    OUTPUT = Output("the selected elements; one row per array with loop")

    def _layout(self, size):
        """(number of arrays, their length) the selection is applied to."""
        if self.honour_loop and self.loop and self.array_length > 0 and \
                size // self.array_length > 1:
            return size // self.array_length, self.array_length
        return 1, size

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape is None:
            return
        k = self.selection.size
        if k == 0:
            raise ValueError("selection is empty: give the positions to output, such as "
                             "selection=\"1 3\"")
        n, _ = self._layout(int(np.prod(shape)))
        self.set_output_shape("OUTPUT", (n, k) if n > 1 else (k,))

    def init(self):
        n, length = self._layout(self.INPUT.size)
        index = self.selection.astype(np.int64)
        if np.any(index != self.selection):
            self.fatal_error(f"selection {self.selection.tolist()} must hold whole positions "
                             f"from 1 to {length}")
            return
        self._inside = (index >= 1) & (index <= length)
        if not self._inside.all():
            self.warning(f"selection {self.selection.tolist()} has positions outside 1 ... "
                         f"{length}: they give 0")
        self._index = np.where(self._inside, index - 1, 0)
        self._arrays = self.INPUT.reshape(-1)[:n * length].reshape(n, length)
        self._out = self.OUTPUT.reshape(n, -1)

    def tick(self):
        np.take(self._arrays, self._index, axis=1, out=self._out)
        self._out[:, ~self._inside] = 0
