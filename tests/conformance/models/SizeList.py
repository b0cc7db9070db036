"""Test-only: OUTPUT is shaped by a string parameter that holds a size list."""
from ikaros.module import Module, Output, Parameter


class SizeList(Module):
    """OUTPUT has the shape that ``size`` lists and holds its element count."""
    size = Parameter("2,3", "a size list, such as 2,3", type="string")
    OUTPUT = Output("the element count in every element", shape="@size")

    def tick(self):
        self.OUTPUT[...] = self.OUTPUT.size
