"""KernelSizeTestModule: an output shaped by a size list."""
from ikaros.module import Output, Parameter

from ikaros.testsupport._internal import InternalModule


class KernelSizeTestModule(InternalModule):
    """OUTPUT has the shape given by ``size`` (a comma list of sizes; each may be an
    expression). Prints ``SIZE 2x3`` at init."""

    size = Parameter("1", "the output's shape, as a comma list")
    OUTPUT = Output("zeros of the given shape", shape="@size")

    def init(self):
        self.print(f"SIZE {'x'.join(map(str, self.OUTPUT.shape))}")
