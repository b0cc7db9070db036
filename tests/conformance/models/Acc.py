"""Test-only accumulator of fixed size 1: OUTPUT = 1 + sum(INPUT); init writes 0."""
from ikaros.module import Input, Module, Output


class Acc(Module):
    """One plus the sum of the input."""
    INPUT = Input("anything")
    OUTPUT = Output("1 + sum(INPUT)", size="1")

    def init(self):
        self.OUTPUT[...] = 0

    def tick(self):
        self.OUTPUT[...] = 1 + float(self.INPUT.sum())
