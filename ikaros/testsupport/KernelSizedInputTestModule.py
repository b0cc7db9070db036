"""KernelSizedInputTestModule: an input of fixed size 4."""
from ikaros.module import Input, Output

from ikaros.testsupport._internal import InternalModule


class KernelSizedInputTestModule(InternalModule):
    """INPUT has the fixed size 4 (connections write into a part of it); OUTPUT copies it.
    Prints ``INPUT <shape> = <values>`` (or ``INPUT unconnected``) every tick."""

    INPUT = Input("fixed size 4", optional=True, size="4")
    OUTPUT = Output("a copy of INPUT", shape="4")

    def tick(self):
        if self.INPUT is None:
            self.print("INPUT unconnected")
            return
        self.OUTPUT[...] = self.INPUT
        values = " ".join(f"{v:g}" for v in self.INPUT.tolist())
        self.print(f"INPUT {'x'.join(map(str, self.INPUT.shape))} = {values}")
