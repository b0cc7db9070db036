"""FanOut: splits an interleaved matrix into separate matrices."""
import numpy as np

from ikaros.module import Input, Module, Parameter


class FanOut(Module):
    """The inverse of FanIn: INPUT is a matrix made of cells of ``cell_size_y`` rows by
    ``cell_size_x`` columns, and output OUTPUTk (k = 1 .. ``outputs``) collects the element at
    one position inside every cell. Positions are numbered row by row inside the cell, so
    OUTPUTk holds INPUT[r::cell_size_y, c::cell_size_x] with k - 1 = r * cell_size_x + c;
    each output has rows/cell_size_y rows and cols/cell_size_x columns (partial cells at
    the right and bottom edges are left out). A 1-D input is one row. Only the first ``outputs``
    positions are used, and outputs beyond the number of positions stay 0 (a warning says
    so); what Ikaros 2 does when ``outputs`` differs from the number of positions no
    reference or golden file gives, so this is this project's reading."""

    outputs = Parameter(1, "number of outputs, OUTPUT1 .. OUTPUTn; normally cell_size_x * "
                        "cell_size_y", type="int")
    cell_size_x = Parameter(1, "columns of a cell", type="int")
    cell_size_y = Parameter(1, "rows of a cell", type="int")
    debug = Parameter(False, "print the outputs on every tick")
    INPUT = Input("the interleaved matrix")

    def configure(self):
        if self.outputs < 1 or self.cell_size_x < 1 or self.cell_size_y < 1:
            raise ValueError("outputs, cell_size_x and cell_size_y must be at least 1")
        for k in range(1, self.outputs + 1):
            self.add_output(f"OUTPUT{k}", description=f"the elements at cell position {k}")

    def set_sizes(self):
        shape = self.input_shape("INPUT")
        if shape is None:
            return
        if len(shape) == 1:
            if self.cell_size_y != 1:
                raise ValueError("a 1-D INPUT needs cell_size_y = 1")
            out = (shape[0] // self.cell_size_x,)
        else:
            out = tuple(shape[:-2]) + (shape[-2] // self.cell_size_y,
                                       shape[-1] // self.cell_size_x)
        if 0 in out:
            raise ValueError(f"INPUT of shape {shape} is smaller than one cell "
                             f"({self.cell_size_y} x {self.cell_size_x})")
        for k in range(1, self.outputs + 1):
            self.set_output_shape(f"OUTPUT{k}", out)

    def init(self):
        cx, cy = self._cx, self._cy = self.cell_size_x, self.cell_size_y
        cells = cx * cy
        if self.outputs != cells:
            self.warning(f"outputs = {self.outputs} but a cell has {cells} positions; "
                         + ("positions past the last output are dropped" if self.outputs < cells
                            else "outputs past the last position stay 0"))
        self._parts = []              # (output, first row, first column) of each position
        for k in range(min(self.outputs, cells)):
            r, c = divmod(k, cx)
            self._parts.append((getattr(self, f"OUTPUT{k + 1}"), r, c))
        for k in range(cells, self.outputs):
            getattr(self, f"OUTPUT{k + 1}").fill(0)

    def tick(self):
        cx, cy = self._cx, self._cy
        x = self.INPUT
        for out, r, c in self._parts:
            if x.ndim == 1:
                out[...] = x[c::cx][:out.shape[0]]
            else:
                out[...] = x[..., r::cy, c::cx][..., :out.shape[-2], :out.shape[-1]]
        if self.debug:
            for k, (out, _, _) in enumerate(self._parts, 1):
                self.print(f"OUTPUT{k}: {np.array2string(out)}")
