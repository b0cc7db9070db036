"""SelectRow: one row of a matrix."""
from ikaros.module import Input, Module, Output, Parameter


class SelectRow(Module):
    """Outputs row ``selected_row`` (counted from 0) of the input matrix as a 1-D array with
    one element per column. A 1-D input is one row; an input of higher rank is seen as rows of
    its last dimension. The row can be changed while the model runs. A row outside the matrix
    gives an output of 0 and a warning (Ikaros 2 read outside the input)."""

    selected_row = Parameter(0, "the row to output, counted from 0", type="int")
    INPUT = Input("the matrix to pick a row from")
    OUTPUT = Output("the selected row", shape="INPUT.cols")

    def init(self):
        self._rows = self.INPUT.reshape(-1, self.OUTPUT.size)
        self._warned = False

    def tick(self):
        row = self.selected_row
        if 0 <= row < self._rows.shape[0]:
            self.OUTPUT[...] = self._rows[row]
            return
        self.OUTPUT.fill(0)
        if not self._warned:
            self._warned = True
            self.warning(f"selected_row {row} is outside the input's rows "
                         f"0..{self._rows.shape[0] - 1}; the output is 0")
