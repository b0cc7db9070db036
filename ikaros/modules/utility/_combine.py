"""A base for the Ikaros 3 element-wise combinations of two inputs (And, Or, Xor, Maximum,
Minimum)."""
from ikaros.module import Input, Module, Output


class Combine(Module):
    """INPUT1 and INPUT2 must have exactly the same shape (as in Ikaros 3, where different
    shapes stop the run with "Matrix sizes must match"); ``combine(a, b, out)`` computes the
    output."""

    INPUT1 = Input("the first operand")
    INPUT2 = Input("the second operand (Ikaros 3 marks it optional, but stops the run when "
                   "it is missing; here it is required)")
    OUTPUT = Output("the combination of INPUT1 and INPUT2, element by element",
                    size_set="INPUT1")

    def init(self):
        if self.INPUT1.shape != self.INPUT2.shape:
            self.fatal_error(f"INPUT1 and INPUT2 must have the same shape (Matrix sizes must "
                             f"match): INPUT1 is {self.INPUT1.shape}, INPUT2 "
                             f"{self.INPUT2.shape}")

    def tick(self):
        type(self).combine(self.INPUT1, self.INPUT2, self.OUTPUT)
