"""Median: the median of all elements of the input (Ikaros 3)."""
import numpy as np

from ikaros.module import Input, Module, Output


class Median(Module):
    """Outputs the median of all elements of the input: the middle element after sorting,
    or the mean of the two middle ones for an even count. An empty input stops the run
    with an error, as in Ikaros 3. New in Ikaros 3."""

    INPUT = Input("the values, of any shape")
    OUTPUT = Output("the median of all input elements", size="1")

    def init(self):
        if self.INPUT.size == 0:
            self.fatal_error("the input is empty: an empty matrix has no median")

    def tick(self):
        v = np.sort(self.INPUT, axis=None)
        n = v.size
        self.OUTPUT[0] = v[n // 2] if n % 2 else (v[n // 2 - 1] + v[n // 2]) / np.float32(2)
