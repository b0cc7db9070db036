"""LocalApproximator: estimates an output from nearby examples."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class LocalApproximator(Module):
    """Estimates the output for INPUT from a set of nearby examples, such as the neighbour
    tables of a KNN module: row i of INPUT_TABLE is the input of example i and row i of
    OUTPUT_TABLE its output. With ``linear_approximation`` an affine map y = A x + b is fitted
    to the examples by least squares and evaluated at INPUT (with too few examples to fix the
    map, the least-norm slope is used, so identical inputs give their mean output). With
    ``average`` the output is the mean of the example outputs. With
    ``distance_weighted_average`` each example counts 1 / d, d being the Euclidean distance of
    its input to INPUT; an example at distance 0 gives its output exactly (the mean of them
    if there are several). When the optional DISTANCE_TABLE is connected, the examples with a
    negative distance (KNN's mark for a missing neighbour) are left out. OUTPUT is 0 while
    there is no example. The class is not in Ikaros 3, and no reference gives Ikaros 2's
    computation beyond the catalogue's one line (local linear regression, a plain or a
    distance-weighted average): these formulas are this project's reading of it."""

    type = Parameter("linear_approximation", "linear_approximation: a local least-squares "
                     "affine fit; average: the mean output; distance_weighted_average: the "
                     "mean output weighted by 1 / distance",
                     options="linear_approximation/average/distance_weighted_average")
    INPUT_TABLE = Input("the inputs of the examples, one row each")
    OUTPUT_TABLE = Input("the outputs of the examples, one row each")
    INPUT = Input("the input whose output is estimated")
    DISTANCE_TABLE = Input("the distances of the examples (from KNN); examples with a negative "
                           "distance are left out", optional=True)
    OUTPUT = Output("the estimated output")

    def set_sizes(self):
        out, inp = self.input_shape("OUTPUT_TABLE"), self.input_shape("INPUT_TABLE")
        point = self.input_shape("INPUT")
        if out is None or inp is None or point is None:
            return
        n = max(1, int(np.prod(point)))
        k = max(1, inp[0] if len(inp) > 1 else int(np.prod(inp)) // n)
        self.set_output_shape("OUTPUT", (max(1, int(np.prod(out)) // k),))

    def init(self):
        n = self.INPUT.size
        if self.INPUT_TABLE.size % n:
            raise ValueError(f"INPUT_TABLE ({self.INPUT_TABLE.size} elements) is not made of "
                             f"rows of INPUT's {n} elements")
        self._x = self.INPUT_TABLE.reshape(-1, n)
        k, m = len(self._x), self.OUTPUT.size
        if self.OUTPUT_TABLE.size != k * m:
            raise ValueError(f"OUTPUT_TABLE has {self.OUTPUT_TABLE.size} elements, not one row "
                             f"of {m} for each of the {k} rows of INPUT_TABLE")
        self._y = self.OUTPUT_TABLE.reshape(k, m)
        if self.DISTANCE_TABLE is not None and self.DISTANCE_TABLE.size != k:
            raise ValueError(f"DISTANCE_TABLE has {self.DISTANCE_TABLE.size} elements but "
                             f"INPUT_TABLE has {k} rows")

    def tick(self):
        x, y = self._x, self._y
        if self.DISTANCE_TABLE is not None:
            keep = self.DISTANCE_TABLE.reshape(-1) >= 0
            x, y = x[keep], y[keep]
        if len(x) == 0:
            self.OUTPUT[...] = 0
            return
        x, y = x.astype(np.float64), y.astype(np.float64)
        point = self.INPUT.reshape(-1).astype(np.float64)
        if self.type == "average":
            self.OUTPUT[...] = y.mean(axis=0)
        elif self.type == "distance_weighted_average":
            d = np.sqrt(np.sum((x - point) ** 2, axis=1))
            zero = d == 0
            if np.any(zero):
                self.OUTPUT[...] = y[zero].mean(axis=0)
            else:
                w = 1.0 / d
                self.OUTPUT[...] = w @ y / w.sum()
        else:
            mean_x, mean_y = x.mean(axis=0), y.mean(axis=0)
            slope = np.linalg.lstsq(x - mean_x, y - mean_y, rcond=None)[0]
            self.OUTPUT[...] = mean_y + (point - mean_x) @ slope
