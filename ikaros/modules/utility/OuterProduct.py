"""OuterProduct: the outer product of two vectors."""
import numpy as np

from ikaros.module import Input, Module, Output


class OuterProduct(Module):
    """Outputs the outer product of the two inputs, each read as a flat vector: a matrix with
    one row per element of INPUT1 and one column per element of INPUT2, OUTPUT[j][i] =
    INPUT1[j] * INPUT2[i]. (Ikaros 2 gave the matrix INPUT2-many rows and INPUT1-many
    columns while filling it as above, which reads past the inputs when their sizes differ;
    here the shape follows the formula.)"""

    INPUT1 = Input("the column vector: one output row per element")
    INPUT2 = Input("the row vector: one output column per element")
    OUTPUT = Output("the outer product, (size of INPUT1) x (size of INPUT2)",
                    shape="INPUT1.size, INPUT2.size")

    def init(self):
        self._a = self.INPUT1.reshape(-1, 1)
        self._b = self.INPUT2.reshape(1, -1)

    def tick(self):
        np.multiply(self._a, self._b, out=self.OUTPUT)
