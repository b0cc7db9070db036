"""A base for And, Or and Xor: scalar in Ikaros 2, element by element in Ikaros 3."""
import numpy as np

from ikaros.module import Output, Parameter

from ._combine import Combine


class Logic(Combine):
    """In an Ikaros 2 file (as Ikaros 2 computes, checked against the original) the class
    is scalar: it compares the first elements of INPUT1 and INPUT2 with ``threshold`` (a
    value is true when it is above it), writes ``high`` into the one-element OUTPUT when
    the combination is true and ``low`` otherwise, and the opposite into the one-element
    INVERSE. Further elements of the inputs are not used, whatever their shapes. In an
    Ikaros 3 file (dialect 3) it works element by element: INPUT1 and INPUT2 must have
    exactly the same shape (as in Ikaros 3, where different shapes stop the run with
    "Matrix sizes must match"), any non-zero value (a negative one or NaN included) is
    true, OUTPUT has the inputs' shape and holds 1 or 0, and there is no INVERSE; the
    threshold, high and low parameters are not used. ``operation`` is the NumPy logical
    function of the subclass."""

    operation = staticmethod(np.logical_and)

    threshold = Parameter(0.5, "Ikaros 2: an input is true when its first element is above "
                          "this")
    high = Parameter(1.0, "Ikaros 2: OUTPUT when the combination is true (INVERSE when "
                     "false)")
    low = Parameter(0.0, "Ikaros 2: OUTPUT when the combination is false (INVERSE when "
                    "true)")
    OUTPUT = Output("Ikaros 2: high or low (one element); Ikaros 3: the combination of "
                    "INPUT1 and INPUT2, element by element")

    def configure(self):
        if self.dialect != "3":
            self.add_output("INVERSE", (1,), "Ikaros 2: low when OUTPUT is high, high when "
                            "it is low")

    def set_sizes(self):
        if self.dialect != "3":
            self.set_output_shape("OUTPUT", (1,))
            return
        shape = self.input_shape("INPUT1")
        if shape is not None:
            self.set_output_shape("OUTPUT", shape)

    def init(self):
        if self.dialect == "3":
            super().init()

    def threshold_2(self) -> float:
        """Ikaros 2: the value INPUT2's first element must exceed to be true."""
        return self.threshold

    def tick(self):
        if self.dialect == "3":
            type(self).operation(self.INPUT1, self.INPUT2, out=self.OUTPUT, casting="unsafe")
            return
        true = type(self).operation(self.INPUT1.flat[0] > np.float32(self.threshold),
                                    self.INPUT2.flat[0] > np.float32(self.threshold_2()))
        self.OUTPUT[0] = self.high if true else self.low
        self.INVERSE[0] = self.low if true else self.high
