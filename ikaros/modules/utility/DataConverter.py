"""DataConverter: copies an input into an output of a given size."""
from ikaros.module import Input, Module, Output, Parameter


class DataConverter(Module):
    """Copies the input, element by element in row order, into an output of
    ``output_size_y`` rows and ``output_size_x`` columns: a reshape. The original stopped with
    an error when the sizes differ; here the module warns once in init, copies as many
    elements as fit and leaves the rest of the output 0."""

    output_size_x = Parameter(4, "columns of the output", type="int")
    output_size_y = Parameter(4, "rows of the output", type="int")
    INPUT = Input("the values to reshape")
    OUTPUT = Output("the input laid out row by row in the new shape",
                    size_param_x="output_size_x", size_param_y="output_size_y")

    def init(self):
        self._n = min(self.INPUT.size, self.OUTPUT.size)
        if self.INPUT.size != self.OUTPUT.size:
            self.warning(f"the input has {self.INPUT.size} elements and the output "
                         f"{self.OUTPUT.size}; {self._n} are copied")
        self._src = self.INPUT.reshape(-1)[:self._n]
        self._dst = self.OUTPUT.reshape(-1)[:self._n]
        self.OUTPUT.fill(0)

    def tick(self):
        self._dst[...] = self._src
