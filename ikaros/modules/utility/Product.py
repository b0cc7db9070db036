"""Product: the product of all elements of the input."""
import numpy as np

from ikaros.module import Input, Module, Output


class Product(Module):
    """Outputs the product of all elements of INPUT (of any shape) as a single element. The
    product is accumulated in double precision and then stored as float32."""

    INPUT = Input("the values to multiply together")
    OUTPUT = Output("the product of all input elements", size="1")

    def tick(self):
        self.OUTPUT[0] = np.prod(self.INPUT, dtype=np.float64)
