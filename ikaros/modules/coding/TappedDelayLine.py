"""TappedDelayLine: the recent history of each input element."""
from ikaros.module import Input, Module, Output, Parameter


class TappedDelayLine(Module):
    """Passes each input element through a delay line of ``no_of_taps`` taps, a "complete
    serial compound" (Sutton & Barto, 1990). On every tick the rows move one step down and the
    input enters row 0, so row k holds the input from k ticks ago (row 0 is the current
    input). OUTPUT has one row per tap and one column per element of INPUT's first row (as in
    Ikaros 2, which sizes it by INPUT's columns: of a matrix input only the first row goes
    through the line, as the golden files show); it is 0 before the line has filled."""

    no_of_taps = Parameter(10, "the length of the delay line", type="int")
    INPUT = Input("the signal")
    OUTPUT = Output("the delay line: row k is the input (its first row) k ticks ago",
                    shape="@no_of_taps, INPUT.cols")

    def init(self):
        self._x = self.INPUT.reshape(-1)[:self.OUTPUT.shape[1]]

    def tick(self):
        out = self.OUTPUT
        out[1:] = out[:-1]          # NumPy copies overlapping slices correctly
        out[0] = self._x
