"""Test-only module with one output per size rule."""
from ikaros.module import Input, Module, Output, Parameter


class Sizes(Module):
    """Outputs sized by the Ikaros 2 size_* rules and Ikaros 3 shape expressions."""
    n = Parameter(5, "a size", type="int")
    w = Parameter(3, "a width", type="int")
    h = Parameter(2, "a height", type="int")
    INPUT = Input("the sizing input")
    INPUT2 = Input("a second sizing input", optional=True)
    LIT = Output("size=3", size="3")
    LITXY = Output("size_x=4 size_y=2", size_x="4", size_y="2")
    PARAM = Output("size_param=n", size_param="n")
    PARAMXY = Output("size_param_x=w size_param_y=h", size_param_x="w", size_param_y="h")
    SET = Output("size_set=INPUT", size_set="INPUT")
    SETXY = Output("size_set_x=INPUT size_set_y=INPUT2", size_set_x="INPUT",
                   size_set_y="INPUT2")
    SHAPE = Output("shape=INPUT.shape", shape="INPUT.shape")
    EXPR = Output("an arithmetic shape", shape="@h, INPUT.size*2+1")
    TRANS = Output("INPUT transposed", shape="INPUT.cols, INPUT.rows")

    def tick(self):
        pass
