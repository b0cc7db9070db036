"""ShapedParameterTestModule: the implementation of ShapedParameterTestModule.ikc."""
from ikaros.testsupport._internal import InternalModule, text


class ShapedParameterTestModule(InternalModule):
    """Prints the parameters its .ikc declares at init, as ``PARAMETERS name=value ...``
    with the shape of each matrix (``sequences=4x3:[[0,0,0],...]``)."""

    def init(self):
        items = []
        for p in self.description.parameters:
            value = getattr(self, p.name)
            shape = "x".join(map(str, value.shape)) + ":" if hasattr(value, "shape") else ""
            items.append(f"{p.name}={shape}{text(value)}")
        self.print("PARAMETERS " + " ".join(items))
