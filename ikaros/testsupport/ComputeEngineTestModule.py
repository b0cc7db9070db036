"""ComputeEngineTestModule: checks what the language computed from the expressions its model
gives it (this project's counterpart of Ikaros 3's compute-engine self-test, TESTS.md row
240)."""
import numpy as np

from ikaros.module import Input, Parameter

from ikaros.testsupport._internal import InternalModule, text

#: the value each parameter must have after the language has evaluated the model's expression
VALUES = {
    "arithmetic": 14.0, "parentheses": 20.0, "division": 2.5, "negation": 4.0,
    "inherited": 5.0, "block_path": 7.5, "absolute_path": 8.0, "braces": "6x4",
    "braced_paths": "7.5/8", "matrix": [[2, 6], [2, 16]], "rows": 3, "cols": 4,
}

#: the shape each shape expression (a ``shape_*`` parameter) must give its output, when
#: INPUT is 2x3x4, k is 2 and ``matrix`` is 2x2
SHAPES = {
    "shape_input": (2, 3, 4), "shape_slice": (3, 4), "shape_index": (4,),
    "shape_size": (24,), "shape_rank": (3,), "shape_list": (3, 4),
    "shape_arithmetic": (2, 8), "shape_optional": (3,), "shape_matrix": (2, 4),
    "shape_axes": (4, 3, 2),
}


class ComputeEngineTestModule(InternalModule):
    """Checks at init that its parameters have the values the model's expressions must give
    (variables, arithmetic, inherited and chained variables, data-block paths, ``{...}``,
    matrix elements), and that each ``shape_*`` parameter, a shape expression
    (``INPUT.shape``, ``INPUT.shape[1:3]``, ``INPUT.size``, ``INPUT.size_x``,
    ``@rows, @cols``, ``optional(...)``, ...), sizes the output of that name as it must. Prints ``COMPUTE ENGINE TEST OK``; the first
    mismatch is a fatal error naming it."""

    arithmetic = Parameter(0.0, "@a+@b*@c: 14")
    parentheses = Parameter(0.0, "(@a+@b)*@c: 20")
    division = Parameter(0.0, "@n/4: 2.5")
    negation = Parameter(0.0, "-(@a-@c)*2: 4")
    inherited = Parameter(0.0, "a chained variable of an enclosing group: 5")
    block_path = Parameter(0.0, "Test.Data.@value: 7.5")
    absolute_path = Parameter(0.0, ".Blocks.Inner.@value: 8")
    braces = Parameter("", "{@a*@b}x{@c}: 6x4")
    braced_paths = Parameter("", "{.Data.value}/{.Blocks.Inner.value}: 7.5/8")
    matrix = Parameter([[0]], "{@a}, @b*2; 1+1, {@c*@c}: [[2,6],[2,16]]", type="matrix")
    rows = Parameter(0, "@a+1: 3", type="int")
    cols = Parameter(0, "@c: 4", type="int")
    k = Parameter(2, "a kernel size for shape_arithmetic", type="int")
    zero = Parameter(0, "0, for shape_optional", type="int")
    shape_input = Parameter("", "INPUT.shape: 2x3x4")
    shape_slice = Parameter("", "INPUT.shape[1:3]: 3x4")
    shape_index = Parameter("", "INPUT.shape[2]: 4")
    shape_size = Parameter("", "INPUT.size: 24")
    shape_rank = Parameter("", "INPUT.rank: 3")
    shape_list = Parameter("", "@rows, @cols: 3x4")
    shape_arithmetic = Parameter("", "INPUT.shape[1]-@k+1, @cols*2: 2x8")
    shape_optional = Parameter("", "@rows, optional(@zero): 3")
    shape_matrix = Parameter("", "matrix.rows, matrix.cols*2: 2x4")
    shape_axes = Parameter("", "INPUT.size_x, INPUT.size_y, INPUT.size_z: 4x3x2")
    INPUT = Input("a 2x3x4 array whose shape the shape expressions read")

    def configure(self):
        for name in SHAPES:
            self.add_output(name.upper(), shape=getattr(self, name))

    def init(self):
        mismatch = self._first_mismatch()
        if mismatch:
            self.fatal_error(f"COMPUTE ENGINE TEST FAILED: {mismatch}")
        else:
            self.print("COMPUTE ENGINE TEST OK")

    def _first_mismatch(self) -> str | None:
        for name, expected in VALUES.items():
            value = getattr(self, name)
            same = (np.array_equal(value, expected) if isinstance(value, np.ndarray)
                    else value == expected and type(value) is type(expected))
            if not same:
                wanted = np.array(expected) if isinstance(expected, list) else expected
                return f"{name} is {text(value)}, expected {text(wanted)}"
        for name, expected in SHAPES.items():
            shape = self.output_shape(name.upper())
            if shape != expected:
                return (f"{name} ({getattr(self, name)!r}) gives the shape {shape}, expected "
                        f"{expected}")
        return None
