"""Polynomial: a polynomial of each input element."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Polynomial(Module):
    """Applies a polynomial without constant term to every element of the input, as Ikaros 2
    does: OUTPUT = c1*x + c2*x^2 + ... + cn*x^n, where n is ``order`` and c1..cn are the
    first n values of ``coefficients``. Missing coefficients are 0 (with a warning), and
    extra ones are ignored. The defaults (order 1, coefficient 1) copy the input."""

    order = Parameter(1, "the highest power of the input (the number of coefficients used)",
                      type="int")
    coefficients = Parameter("1", "the coefficients of x, x^2, ... x^order", type="array")
    INPUT = Input("the values x")
    OUTPUT = Output("the polynomial of each element", size_set="INPUT")

    def init(self):
        self._input = self.INPUT.reshape(self.OUTPUT.shape)
        self._warned = False

    def _coefficients(self):
        order = max(0, int(self.order))
        given = np.asarray(self.coefficients, dtype=np.float32).reshape(-1)
        if given.size < order and not self._warned:
            self._warned = True
            self.warning(f"order is {order} but only {given.size} coefficients are given; "
                         f"the missing ones are 0")
        c = np.zeros(order, dtype=np.float32)
        n = min(order, given.size)
        c[:n] = given[:n]
        return c

    def tick(self):
        # Horner's rule from the highest power down: ((cn*x + c(n-1))*x + ...)*x
        self.OUTPUT.fill(0)
        for c in self._coefficients()[::-1]:
            self.OUTPUT += c
            self.OUTPUT *= self._input
