"""DynamicMatrixSource: a dynamic output that grows by one row per tick, and starts again."""
from ikaros.module import Output, Parameter

from ikaros.testsupport._internal import InternalModule, grown


class DynamicMatrixSource(InternalModule):
    """OUTPUT is a dynamic output of capacity ``max_rows`` x ``columns``. On tick t (the
    first tick is 0, or 1 in an Ikaros 3 file) it has ``t % max_rows + 1`` rows and element [r, c] is
    100 t + 10 r + c; it has no rows in init."""

    max_rows = Parameter(4, "the capacity's rows")
    columns = Parameter(2, "the capacity's columns")
    OUTPUT = Output("the growing matrix", dynamic=True, capacity="@max_rows, @columns")

    def tick(self):
        self.OUTPUT.set(grown(self.clock.tick, self.max_rows, self.columns))
