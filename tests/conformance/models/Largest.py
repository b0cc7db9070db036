"""Test-only: OUTPUT is sized by size_set="INPUT1,INPUT2" and holds the sum of both inputs'
elements in every element."""
from ikaros.module import Input, Module, Output


class Largest(Module):
    """Sized like the larger of its inputs; every element is the sum of all input elements."""
    INPUT1 = Input("one input")
    INPUT2 = Input("another input")
    OUTPUT = Output("the sum of all input elements", size_set="INPUT1,INPUT2")

    def tick(self):
        self.OUTPUT[...] = self.INPUT1.sum() + self.INPUT2.sum()
