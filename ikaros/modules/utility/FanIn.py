"""FanIn: interleaves several matrices into one."""
from ikaros.module import Module, Output, Parameter


class FanIn(Module):
    """Interleaves ``inputs`` matrices of the same size, INPUT1, INPUT2, ..., into one
    matrix made of cells of ``cell_size_y`` rows and ``cell_size_x`` columns: cell (j, i)
    holds element (j, i) of every input, and input k (counting from 1) fills position
    ((k-1) // cell_size_x, (k-1) % cell_size_x) of each cell. The output has
    rows*cell_size_y rows and cols*cell_size_x columns; a 1-D input counts as one row. With
    fewer inputs than positions in a cell the free positions are 0 (the original read past
    its inputs); inputs beyond cell_size_x*cell_size_y are ignored with a warning. FanOut
    splits such a matrix again."""

    inputs = Parameter(1, "the number of inputs (INPUT1, INPUT2, ...)", type="int")
    cell_size_x = Parameter(1, "columns of a cell", type="int")
    cell_size_y = Parameter(1, "rows of a cell", type="int")
    debug = Parameter(False, "print the output on every tick")
    OUTPUT = Output("the interleaved matrix")

    def configure(self):
        if self.inputs < 1:
            raise ValueError(f"inputs must be at least 1, not {self.inputs}")
        if self.cell_size_x < 1 or self.cell_size_y < 1:
            raise ValueError("cell_size_x and cell_size_y must be at least 1")
        for k in range(1, self.inputs + 1):
            self.add_input(f"INPUT{k}", description=f"matrix number {k}")

    def _matrix_shape(self, shape):
        if len(shape) == 0:
            return (1, 1)
        if len(shape) == 1:
            return (1, shape[0])
        rows = 1
        for s in shape[:-1]:
            rows *= s
        return (rows, shape[-1])

    def set_sizes(self):
        shapes = [self.input_shape(f"INPUT{k}") for k in range(1, self.inputs + 1)]
        if any(s is None for s in shapes):
            return
        rows, cols = self._matrix_shape(shapes[0])
        for k, s in enumerate(shapes[1:], 2):
            if self._matrix_shape(s) != (rows, cols):
                raise ValueError(f"INPUT{k} has shape {s} but INPUT1 has {shapes[0]}; all "
                                 f"inputs must have the same size")
        self.set_output_shape("OUTPUT", (rows * self.cell_size_y, cols * self.cell_size_x))

    def init(self):
        cx, cy = self.cell_size_x, self.cell_size_y
        rows, cols = self.OUTPUT.shape[0] // cy, self.OUTPUT.shape[1] // cx
        if self.inputs > cx * cy:
            self.warning(f"only {cx * cy} of the {self.inputs} inputs fit in a cell of "
                         f"{cy} x {cx}; the others are ignored")
        cells = self.OUTPUT.reshape(rows, cy, cols, cx)
        self._pairs = []
        for k in range(min(self.inputs, cx * cy)):
            jj, ii = divmod(k, cx)
            src = getattr(self, f"INPUT{k + 1}").reshape(rows, cols)
            self._pairs.append((cells[:, jj, :, ii], src))
        self.OUTPUT.fill(0)

    def tick(self):
        for dst, src in self._pairs:
            dst[...] = src
        if self.debug:
            self.print("\n" + "\n".join(" ".join(f"{v:g}" for v in row) for row in self.OUTPUT))
