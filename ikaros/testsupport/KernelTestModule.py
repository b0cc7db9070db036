"""KernelTestModule: a parameter of every type, printed at init."""
from ikaros.module import Input, Output, Parameter

from ikaros.testsupport._internal import InternalModule, text


class KernelTestModule(InternalModule):
    """Has a parameter of every type and prints their values at init as
    ``PARAMETERS a=... b=...`` (in declaration order). ``codeparam_2`` is set in code
    in ``configure``, so the file's value never reaches it. INPUT is optional; OUTPUT is a
    copy of INPUT's first element (1 element)."""

    a = Parameter("3", "a string")
    b = Parameter(True, "a bool")
    c = Parameter(6.0, "a number")
    d = Parameter("text", "a string")
    e = Parameter([[0, 0, 0]] * 3, "a matrix", type="matrix")
    f1 = Parameter("B", "an option, by label", options="A,B,C")
    f2 = Parameter("B", "an option string", options="A,B,C")
    f3 = Parameter("B", "an option bool (index 0 is false)", type="bool", options="A,B")
    g = Parameter(0.1, "a rate", type="rate")
    data = Parameter([1, 2, 3, 4], "an array", type="array")
    mdata = Parameter([[1, 2], [3, 4]], "a matrix", type="matrix")
    x = Parameter(7.0, "a number")
    y = Parameter(9.0, "a number")
    codeparam_1 = Parameter(111.0, "a number left at its default")
    codeparam_2 = Parameter(0.0, "a number set in code (999) whatever the file says")
    INPUT = Input("anything", optional=True)
    OUTPUT = Output("INPUT's first element", shape="1")

    def configure(self):
        self.codeparam_2 = 999.0

    def init(self):
        names = [p.name for p in self.description.parameters]
        values = " ".join(f"{n}={text(getattr(self, n))}" for n in names)
        self.print(f"PARAMETERS {values}")

    def tick(self):
        self.OUTPUT[0] = self.INPUT.flat[0] if self.INPUT is not None and self.INPUT.size \
            else 0
