"""OutputAliasTestModule: an output and aliases that view it."""
from ikaros.module import Input, Output

from ikaros.testsupport._internal import InternalModule


class OutputAliasTestModule(InternalModule):
    """OUTPUT has INPUT's shape and holds INPUT + 1 (written in tick). ALL is an alias of
    the whole OUTPUT, ROW of OUTPUT[1] (its second row) and CELL of OUTPUT[1][2] (one
    element); the module writes only OUTPUT."""

    INPUT = Input("any matrix with at least 2 rows and 3 columns")
    OUTPUT = Output("INPUT + 1", shape="INPUT.shape")
    ALL = Output("the whole OUTPUT", alias="OUTPUT")
    ROW = Output("the second row of OUTPUT", alias="OUTPUT[1]")
    CELL = Output("OUTPUT[1][2]", alias="OUTPUT[1][2]")

    def tick(self):
        self.OUTPUT[...] = self.INPUT + 1
