"""InputSelector: passes on one of several inputs."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class InputSelector(Module):
    """Copies one of its ``inputs`` inputs to OUTPUT: SELECT = 0 picks INPUT1, 1 picks INPUT2,
    and so on (SELECT's first element, rounded to the nearest whole number). The inputs are
    named INPUT1 .. INPUTn, or INPUT when there is only one, and must all have the same
    shape, which is the output's. A SELECT outside 0 .. n-1 gives an output of 0 and a
    warning (once until a valid value comes back); Ikaros 2 read past its inputs or
    stopped."""

    inputs = Parameter(2, "number of inputs", type="int", range=(1, None))
    debug = Parameter(False, "print the selected input on every tick")
    SELECT = Input("the index of the input to pass on: 0 for INPUT1, 1 for INPUT2, ...")
    OUTPUT = Output("a copy of the selected input")

    def configure(self):
        if self.inputs < 1:
            raise ValueError(f"inputs must be at least 1, not {self.inputs}")
        self._names = ["INPUT"] if self.inputs == 1 else \
            [f"INPUT{k}" for k in range(1, self.inputs + 1)]
        for k, name in enumerate(self._names):
            self.add_input(name, description=f"the input passed on when SELECT is {k}")

    def set_sizes(self):
        shapes = [self.input_shape(n) for n in self._names]
        if any(s is None for s in shapes):
            return
        for name, shape in zip(self._names, shapes):
            if shape != shapes[0]:
                raise ValueError(f"the inputs must have the same shape: {self._names[0]} is "
                                 f"{shapes[0]}, {name} is {shape}")
        self.set_output_shape("OUTPUT", shapes[0])

    def init(self):
        self._inputs = [getattr(self, n.replace("-", "_")) for n in self._names]
        self._warned = False

    def tick(self):
        index = int(np.floor(float(self.SELECT.flat[0]) + 0.5)) if np.isfinite(
            self.SELECT.flat[0]) else -1
        if 0 <= index < len(self._inputs):
            self.OUTPUT[...] = self._inputs[index]
            self._warned = False
        else:
            self.OUTPUT.fill(0)
            if not self._warned:
                self._warned = True
                self.warning(f"SELECT = {self.SELECT.flat[0]:g} is not an input index "
                             f"(0 .. {len(self._inputs) - 1}); the output is 0")
        if self.debug:
            self.print(f"selected {index}: {np.array2string(self.OUTPUT)}")
