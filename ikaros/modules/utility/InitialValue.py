"""InitialValue: a stock that starts at given values."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class InitialValue(Module):
    """A stock for difference-equation (stock-and-flow) models. The output starts as
    ``data`` (written in init, and on each of the first ``wait`` ticks); after that, on every
    tick where UPDATE is on (its first element is 1 or more; always, when UPDATE is not
    connected), INPUT is added to the output (mode ``accumulate``) or copied to it (mode
    ``copy``). The output has ``outputsize`` elements, or as many as ``data`` when
    outputsize is not given; ``data`` fills it in order and missing values are 0. An INPUT
    with more elements than the output is used for its first elements only, as Ikaros 2
    does (golden files), with a warning; one with fewer is an error (Ikaros 2 would read
    past its end)."""

    outputsize = Parameter(None, "number of elements of the output; unset: the number of "
                           "values in data", type="int")
    data = Parameter("1", "the initial values", type="array")
    wait = Parameter(1, "number of ticks the output holds data before it starts to change",
                     type="int")
    mode = Parameter("accumulate", "accumulate: add INPUT to the output; copy: replace the "
                     "output by INPUT", options="accumulate/copy")
    debug = Parameter(False, "print the output on every tick")
    INPUT = Input("the flow: added to (or copied to) the output")
    UPDATE = Input("when connected, the output changes only on ticks where its first element "
                   "is 1 or more", optional=True)
    OUTPUT = Output("the stock", size_param="outputsize", shape="data.size")

    def init(self):
        n = self.OUTPUT.size
        if self.INPUT.size < n:
            self.fatal_error(f"INPUT has {self.INPUT.size} elements but the output has {n}; "
                             f"it needs at least as many")
            return
        if self.INPUT.size > n:
            self.warning(f"INPUT has {self.INPUT.size} elements and the output {n}: only "
                         f"the first {n} are used, as in Ikaros 2")
        self._input = self.INPUT.reshape(-1)[:n].reshape(self.OUTPUT.shape)
        self._wait = self.wait
        self._write_data()

    def _write_data(self):
        data = np.asarray(self.data, dtype=np.float32).reshape(-1)
        n = min(data.size, self.OUTPUT.size)
        self.OUTPUT[:n] = data[:n]
        self.OUTPUT[n:] = 0

    def tick(self):
        if self._wait > 0:
            self._wait -= 1
            self._write_data()
        elif self.UPDATE is None or self.UPDATE.flat[0] >= 1:
            if self.mode == "copy":
                self.OUTPUT[...] = self._input
            else:
                self.OUTPUT += self._input
        if self.debug:
            self.print(np.array2string(self.OUTPUT))
