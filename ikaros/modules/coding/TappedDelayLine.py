"""TappedDelayLine: the recent history of each input element."""
from ikaros.module import Input, Module, Output, Parameter


class TappedDelayLine(Module):
    """Passes each input element through a delay line of ``no_of_taps`` taps, a "complete
    serial compound" (Sutton & Barto, 1990). On every tick the rows move one step down and the
    input enters row 0, so row k holds the input from k ticks ago (row 0 is the current
    input). OUTPUT has one row per tap and one column per input element; it is 0 before the
    line has filled."""

    no_of_taps = Parameter(10, "the length of the delay line", type="int")
    INPUT = Input("the signal")
    OUTPUT = Output("the delay line: row k is the input k ticks ago",
                    shape="@no_of_taps, INPUT.size")

    def init(self):
        self._x = self.INPUT.reshape(-1)

    def tick(self):
        out = self.OUTPUT
        out[1:] = out[:-1]          # NumPy copies overlapping slices correctly
        out[0] = self._x
