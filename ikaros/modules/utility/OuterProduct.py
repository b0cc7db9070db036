"""OuterProduct: the outer product of two vectors."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class OuterProduct(Module):
    """The outer product of the two inputs, each read as a flat vector a (INPUT1, n1
    elements) and b (INPUT2, n2 elements).

    By default (``result="accumulated"``) as Ikaros 2 computes it (golden files): the
    products are **added** to the output on every tick, which is never cleared, and the
    output has n2 rows and n1 columns (rows and columns swapped) while it is filled row by
    row as out[j][i] += a[j] * b[i] for j < min(n1, n2) and i < n2. With n1 = n2 this is
    the sum over the ticks of the outer product; with n1 > n2 the columns from n2 on stay
    0; with n1 < n2 a row runs on into the next rows, as it does in the original's memory
    (this case is this project's reading: the golden files have no such case), and rows j
    >= n1 are not written. A warning is given when n1 and n2 differ.

    ``result="outer"`` (this project's) gives the outer product of this tick: n1 rows and
    n2 columns, OUTPUT[j][i] = a[j] * b[i]."""

    result = Parameter("accumulated", "accumulated: Ikaros 2's sum over the ticks, n2 x n1; "
                       "outer: this tick's outer product, n1 x n2",
                       options="accumulated/outer", fixed=True)
    INPUT1 = Input("the vector a (read flat)")
    INPUT2 = Input("the vector b (read flat)")
    OUTPUT = Output("the outer product: n1 x n2 (outer) or the accumulated n2 x n1 "
                    "(Ikaros 2)")

    def set_sizes(self):
        a, b = self.input_shape("INPUT1"), self.input_shape("INPUT2")
        if a is None or b is None:
            return
        n1, n2 = int(np.prod(a)), int(np.prod(b))
        self.set_output_shape("OUTPUT", (n1, n2) if self.result == "outer" else (n2, n1))

    def init(self):
        self._a = self.INPUT1.reshape(-1)
        self._b = self.INPUT2.reshape(-1)
        self.OUTPUT.fill(0)
        n1, n2 = self._a.size, self._b.size
        if self.result == "outer":
            return
        if n1 != n2:
            self.warning(f"INPUT1 has {n1} elements and INPUT2 {n2}: as in Ikaros 2 the "
                         f"output has {n2} rows and {n1} columns and only part of the "
                         f"products are added")
        j, i = np.meshgrid(np.arange(min(n1, n2)), np.arange(n2), indexing="ij")
        flat = (j * n1 + i).reshape(-1)
        inside = flat < self.OUTPUT.size
        self._j, self._i = j.reshape(-1)[inside], i.reshape(-1)[inside]
        self._flat = flat[inside]

    def tick(self):
        if self.result == "outer":
            np.multiply(self._a[:, None], self._b[None, :], out=self.OUTPUT)
            return
        added = np.bincount(self._flat, weights=self._a[self._j] * self._b[self._i],
                            minlength=self.OUTPUT.size)
        self.OUTPUT.reshape(-1)[...] += added.astype(np.float32)
