"""KNN_Pick: one answer from the neighbour tables of KNN."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class KNN_Pick(Module):
    """Turns the neighbour tables of a KNN module into one answer. Row i of OUTPUT_TABLE is
    the output of neighbour i and element i of DISTANCE_TABLE its distance; neighbours with a
    negative distance (KNN's mark for "not found") are left out. When a neighbour is at
    distance 0, the answer is its output (the first such). Otherwise, when ``categorical``,
    the answer is the output (class) that the most neighbours share; on a tie the class with
    the nearest member wins, then the one listed first. When not categorical the answer is
    the mean of the outputs. With ``weighed`` each neighbour counts weight_divisor /
    ln(1.0001 + distance) times instead of once, in the vote and in the mean. A row of several
    elements is one class (compared whole) or averaged element by element; a 1-D OUTPUT_TABLE
    is one value per neighbour. CLASS_OUTPUT is 0 while there is no neighbour. (Ikaros 2 let
    a missing neighbour's -1 win as the nearest one.)"""

    categorical = Parameter(True, "yes: a (weighted) majority vote among the classes; no: the "
                            "(weighted) mean of the outputs")
    weighed = Parameter(False, "weigh each neighbour by weight_divisor / ln(1.0001 + distance)")
    weight_divisor = Parameter(1.0, "the numerator of the weight of a neighbour")
    OUTPUT_TABLE = Input("the outputs (classes) of the neighbours, one row each")
    DISTANCE_TABLE = Input("the distances of the neighbours; negative means no neighbour")
    CLASS_OUTPUT = Output("the chosen class, or the mean output")

    def set_sizes(self):
        shape = self.input_shape("OUTPUT_TABLE")
        if shape is not None:
            self.set_output_shape("CLASS_OUTPUT", (shape[-1] if len(shape) > 1 else 1,))

    def init(self):
        k = self.DISTANCE_TABLE.size
        c = self.CLASS_OUTPUT.size
        if self.OUTPUT_TABLE.size != k * c:
            raise ValueError(f"OUTPUT_TABLE has {self.OUTPUT_TABLE.size} elements, not one row "
                             f"of {c} for each of the {k} distances in DISTANCE_TABLE")
        self._table = self.OUTPUT_TABLE.reshape(k, c)
        self._dist = self.DISTANCE_TABLE.reshape(-1)
        self._warned = False

    def tick(self):
        valid = np.flatnonzero(self._dist >= 0)
        if valid.size == 0:
            self.CLASS_OUTPUT[...] = 0
            return
        dist = self._dist[valid].astype(np.float64)
        rows = self._table[valid]
        zero = np.flatnonzero(dist == 0)
        if zero.size:
            self.CLASS_OUTPUT[...] = rows[zero[0]]
            return
        if self.weighed:
            weight = self.weight_divisor / np.log(1.0001 + dist)
        else:
            weight = np.ones_like(dist)
        if not self.categorical:
            total = weight.sum()
            if total == 0:
                if not self._warned:
                    self.warning("the weights sum to 0 (weight_divisor is 0): output set to 0")
                    self._warned = True
                self.CLASS_OUTPUT[...] = 0
            else:
                self.CLASS_OUTPUT[...] = weight @ rows / total
            return
        classes, first, which = np.unique(rows, axis=0, return_index=True,
                                          return_inverse=True)
        which = which.reshape(-1)
        score = np.bincount(which, weights=weight, minlength=len(classes))
        nearest = np.full(len(classes), np.inf)
        np.minimum.at(nearest, which, dist)
        best = np.lexsort((first, nearest, -score))[0]
        self.CLASS_OUTPUT[...] = classes[best]
