"""Test-only module with one parameter of each type; it only holds them."""
from ikaros.module import Module, Output, Parameter


class Par(Module):
    """Holds parameters; OUTPUT = [p, q]."""
    p = Parameter(1.0, "a number")
    q = Parameter(2.0, "another number")
    max = Parameter(0.0, "a number called max")
    k = Parameter(4, "an int")
    flag = Parameter(False, "a bool")
    s = Parameter("default", "a string")
    mode = Parameter("a", "an option", options="a,b,c")
    m = Parameter("0", "a matrix", type="matrix")
    OUTPUT = Output("p and q", size="2")

    def init(self):
        self.tick()

    def tick(self):
        self.OUTPUT[:] = (self.p, self.q)
