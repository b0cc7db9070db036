"""Polynomial: a polynomial of each input element."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Polynomial(Module):
    """Applies a polynomial without constant term to every element of the input, as Ikaros 2
    does (golden files): OUTPUT = c1*x + c2*x^2 + ... + cn*x^n, where c1 ... cn are all the
    values of ``coefficients``. Ikaros 2 takes the number of coefficients given as the
    order: ``order`` does not change the result, and a warning says so when it differs
    from that number. The defaults (coefficient 1) copy the input."""

    order = Parameter(1, "the highest power (Ikaros 2 and this class use as many powers as "
                      "there are coefficients)", type="int")
    coefficients = Parameter("1", "the coefficients of x, x^2, ... (their number is the "
                             "order)", type="array")
    INPUT = Input("the values x")
    OUTPUT = Output("the polynomial of each element", size_set="INPUT")

    def init(self):
        self._input = self.INPUT.reshape(self.OUTPUT.shape)
        n = np.asarray(self.coefficients).size
        if n != self.order:
            self.warning(f"order is {self.order} but {n} coefficients are given: as in "
                         f"Ikaros 2 the polynomial has all {n}")

    def tick(self):
        # Horner's rule from the highest power down: ((cn*x + c(n-1))*x + ...)*x
        self.OUTPUT.fill(0)
        for c in np.asarray(self.coefficients, dtype=np.float32).reshape(-1)[::-1]:
            self.OUTPUT += c
            self.OUTPUT *= self._input
