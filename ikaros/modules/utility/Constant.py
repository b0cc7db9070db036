"""Constant: outputs a fixed array."""
from ikaros.module import Module, Output, Parameter


class Constant(Module):
    """Outputs the array given by ``data`` (``;`` separates rows, nested brackets give higher
    ranks). The size comes from the data, or from ``outputsize`` / ``outputsize_x`` and
    ``outputsize_y``, in which case the data fill the output row by row (missing elements are
    0). The value is written in init and on every tick, so edits to ``data`` take effect.
    The default data is 0 in an Ikaros 2 file and ``1, 2, 3, 4, 5, 6`` in an Ikaros 3 file
    (dialect 3), as in each version."""

    data = Parameter("0", "the values to output (nan and inf allowed)", type="matrix",
                     finite=False, default_v3="1, 2, 3, 4, 5, 6")
    outputsize = Parameter(None, "number of elements of a 1-D output", type="int")
    outputsize_x = Parameter(None, "columns of a 2-D output", type="int")
    outputsize_y = Parameter(None, "rows of a 2-D output", type="int")
    OUTPUT = Output("the constant", size_param_x="outputsize_x", size_param_y="outputsize_y",
                    size_param="outputsize", shape="data.shape")

    compiled_op = "constant"   # an instruction of the compiled tick (ikaros/kernel/compiled/)

    def init(self):
        self.tick()

    def tick(self):
        data = self.data
        if data.shape == self.OUTPUT.shape:
            self.OUTPUT[...] = data
        else:
            flat = self.OUTPUT.reshape(-1)
            n = min(flat.size, data.size)
            flat[:n] = data.reshape(-1)[:n]
            flat[n:] = 0
