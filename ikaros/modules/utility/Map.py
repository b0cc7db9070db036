"""Map: maps values linearly from one range to another."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Map(Module):
    """Maps each element of INPUT linearly from the range low_source .. high_source to the
    range low_target .. high_target: OUTPUT = low_target + (INPUT - low_source) *
    (high_target - low_target) / (high_source - low_source). Values outside the source range
    are extrapolated, not clipped. When high_source equals low_source the output is
    low_target and a warning is given once."""

    low_source = Parameter(0.0, "the input value that maps to low_target")
    high_source = Parameter(1.0, "the input value that maps to high_target")
    low_target = Parameter(0.0, "the output for an input of low_source")
    high_target = Parameter(1.0, "the output for an input of high_source")
    INPUT = Input("the values to map")
    OUTPUT = Output("the mapped values", size_set="INPUT")

    def init(self):
        self._warned = False

    def tick(self):
        span = self.high_source - self.low_source
        if span == 0:
            if not self._warned:
                self._warned = True
                self.warning("high_source equals low_source: the output is low_target")
            self.OUTPUT.fill(self.low_target)
            return
        gain = (self.high_target - self.low_target) / span
        np.subtract(self.INPUT, self.low_source, out=self.OUTPUT)
        self.OUTPUT *= gain
        self.OUTPUT += self.low_target
