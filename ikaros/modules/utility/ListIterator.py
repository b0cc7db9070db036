"""ListIterator: steps through a list, one entry per sync pulse."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class ListIterator(Module):
    """Steps through a list, one entry each tick on which SYNC_IN's first element is not 0
    (every tick when SYNC_IN is not connected), and outputs the current entry on OUTPUT. The
    list is INPUT when that is connected (read anew at each step, so it may change), and
    otherwise ``listdata``. A list of several rows is stepped row by row and OUTPUT has one
    row's elements; a single row is stepped element by element and OUTPUT has one element.
    SYNC_OUT is 1 on the first tick (whatever SYNC_IN is), and on the tick after a step
    that output the last entry (when a repeating list starts again, the tick that outputs
    the first entry), unless that step also output the first entry (a list of one entry);
    0 otherwise. This is Ikaros 2's SYNC_OUT as the golden files show it. After the last
    entry the list starts over when ``repeat`` is set; otherwise the output keeps the last
    entry and further steps do nothing. OUTPUT is 0 until the first step."""

    repeat = Parameter(False, "start over after the last entry")
    listdata = Parameter("0", "the list, when INPUT is not connected: one entry per row, or "
                         "one per element of a single row", type="matrix")
    debug = Parameter(False, "print the index and output on every step")
    INPUT = Input("a list to step through instead of listdata", optional=True)
    SYNC_IN = Input("steps to the next entry when its first element is not 0; unconnected: "
                    "every tick", optional=True)
    SYNC_OUT = Output("1 on the first tick and on the tick after a pass ends, otherwise 0",
                      size="1")
    OUTPUT = Output("the current entry")

    def _list_shape(self):
        shape = self.input_shape("INPUT")
        if shape is None:
            return None
        if shape == ():                      # not connected: listdata
            shape = np.asarray(self.listdata).shape
        return shape

    def set_sizes(self):
        shape = self._list_shape()
        if shape is None:
            return
        if len(shape) == 0 or 0 in shape:
            raise ValueError("the list is empty")
        rows = int(np.prod(shape[:-1])) if len(shape) > 1 else 1
        self.set_output_shape("OUTPUT", (shape[-1],) if rows > 1 else (1,))

    def init(self):
        self._index = 0
        self._stopped = False
        self._pulse = True          # SYNC_OUT of the next tick
        self.OUTPUT.fill(0)
        self.SYNC_OUT.fill(0)

    def _entries(self):
        source = self.INPUT if self.INPUT is not None else np.asarray(self.listdata,
                                                                       np.float32)
        if source.size == 0:
            return None
        if source.ndim > 1 and source.size // source.shape[-1] > 1:
            return source.reshape(-1, source.shape[-1])          # one entry per row
        return source.reshape(-1, 1)                              # one entry per element

    def tick(self):
        self.SYNC_OUT[0] = 1 if self._pulse else 0
        before = self._index
        self._step()
        self._pulse = self._index == 0 and before != 0

    def _step(self):
        step = self.SYNC_IN is None or self.SYNC_IN.flat[0] != 0
        if not step or self._stopped:
            return
        entries = self._entries()
        if entries is None or entries.shape[1] != self.OUTPUT.size:
            self.fatal_error("the list no longer matches the output size")
            return
        if self._index >= len(entries):
            self._index = 0
        self.OUTPUT[...] = entries[self._index].reshape(self.OUTPUT.shape)
        if self.debug:
            self.print(f"index {self._index}: {np.array2string(self.OUTPUT)}")
        self._index += 1
        if self._index >= len(entries):
            self._index = 0
            self._stopped = not self.repeat
