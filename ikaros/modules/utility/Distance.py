"""Distance: the distance between two vectors."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class Distance(Module):
    """Outputs the distance between INPUT1 and INPUT2, seen as two points: euclidean (the
    square root of the sum of squared differences) or cityblock (the sum of absolute
    differences). The inputs must have the same number of elements; their shapes are
    ignored."""

    type = Parameter("euclidean", "the metric", options="euclidean/cityblock")
    INPUT1 = Input("the first point")
    INPUT2 = Input("the second point")
    OUTPUT = Output("the distance between the two points", size="1")

    def init(self):
        if self.INPUT1.size != self.INPUT2.size:
            self.fatal_error(f"INPUT1 and INPUT2 must have the same size; they have "
                             f"{self.INPUT1.size} and {self.INPUT2.size} elements")
            return
        self._a = self.INPUT1.reshape(-1)
        self._b = self.INPUT2.reshape(-1)
        self._diff = np.zeros(self._a.shape, np.float32)

    def tick(self):
        np.subtract(self._a, self._b, out=self._diff)
        if self.type == "cityblock":
            self.OUTPUT[0] = np.abs(self._diff).sum()
        else:
            self.OUTPUT[0] = np.sqrt(np.dot(self._diff, self._diff))
