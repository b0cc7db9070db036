"""TruncateArray: picks chosen elements of an array."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class TruncateArray(Module):
    """Outputs the input elements chosen by ``selection``, a list of positions counted from
    1: selection="4 6" outputs the 4th and 6th elements. With ``loop`` the input is read as
    consecutive arrays of ``array_length`` elements and the selection is taken from each of
    them: when the input holds more than one whole array the output is a matrix with one row
    per array (elements after the last whole array are ignored); otherwise it is 1-D, as
    without ``loop``. (Ikaros 2 declared array_length and loop but always took the selection
    from the start of the input only.) A position outside the input, or outside an array with
    ``loop``, is an error at start-up."""

    array_length = Parameter(16, "the length of each array in the input when loop is on",
                             type="int")
    loop = Parameter(True, "take the selection from every array of array_length elements")
    selection = Parameter("", "the positions to output, counted from 1", type="array")
    INPUT = Input("the array to pick elements from", flatten=True)
    OUTPUT = Output("the selected elements; one row per array with loop")

    def _layout(self, size):
        """(number of arrays, their length) the selection is applied to."""
        if self.loop and self.array_length > 0 and size // self.array_length > 1:
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
        limit = length
        index = self.selection.astype(np.int64)
        if np.any(index != self.selection) or np.any(index < 1) or np.any(index > limit):
            self.fatal_error(f"selection {self.selection.tolist()} must hold whole positions "
                             f"from 1 to {limit}")
            return
        self._index = index - 1
        self._arrays = self.INPUT.reshape(-1)[:n * length].reshape(n, length)
        self._out = self.OUTPUT.reshape(n, -1)

    def tick(self):
        np.take(self._arrays, self._index, axis=1, out=self._out)
