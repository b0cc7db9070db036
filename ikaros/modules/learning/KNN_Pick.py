"""KNN_Pick: one answer from the neighbour tables of KNN."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter


class KNN_Pick(Module):
    """Turns the neighbour tables of a KNN module into one answer, as Ikaros 2 does (the class
    is not in Ikaros 3). Row i of OUTPUT_TABLE is the output of neighbour i and element i of
    DISTANCE_TABLE its distance; when OUTPUT_TABLE has one element per distance, whatever
    its shape, each element is one neighbour's class and CLASS_OUTPUT has one element.
    When ``categorical``, the answer is the output (class) that the most neighbours share;
    on a tie the tied class listed last wins (the golden files show it). When not
    categorical the answer is the mean of the outputs. Every neighbour counts, as in Ikaros
    2, even one that KNN marks as missing (distance -1, output 0): ``skip_missing="yes"``
    (this project's) leaves neighbours of negative distance out (CLASS_OUTPUT is then 0
    while there is none). With ``weighed`` each neighbour counts
    weight_divisor / ln(1.0001 + distance) times instead of once, in the vote and in the
    mean: this weight is this project's reading (no reference gives the formula of Ikaros
    2's weighed mode). A row of several elements is one class (compared whole) or averaged
    element by element."""

    categorical = Parameter(True, "yes: a (weighted) majority vote among the classes; no: the "
                            "(weighted) mean of the outputs")
    weighed = Parameter(False, "weigh each neighbour by weight_divisor / ln(1.0001 + distance)")
    weight_divisor = Parameter(1.0, "the numerator of the weight of a neighbour")
    skip_missing = Parameter(False, "leave out neighbours of negative distance (KNN's "
                             "missing ones); Ikaros 2 counts them")
    OUTPUT_TABLE = Input("the outputs (classes) of the neighbours, one row each")
    DISTANCE_TABLE = Input("the distances of the neighbours; negative means no neighbour")
    CLASS_OUTPUT = Output("the chosen class, or the mean output")

    def set_sizes(self):
        shape, distances = self.input_shape("OUTPUT_TABLE"), self.input_shape("DISTANCE_TABLE")
        if shape is not None and distances is not None:
            one_each = int(np.prod(shape)) == int(np.prod(distances))
            self.set_output_shape("CLASS_OUTPUT", (1 if one_each or len(shape) < 2
                                                   else shape[-1],))

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
        valid = np.flatnonzero(self._dist >= 0) if self.skip_missing else \
            np.arange(self._dist.size)
        if valid.size == 0:
            self.CLASS_OUTPUT[...] = 0
            return
        dist = self._dist[valid].astype(np.float64)
        rows = self._table[valid]
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
        classes, which = np.unique(rows, axis=0, return_inverse=True)
        which = which.reshape(-1)
        score = np.bincount(which, weights=weight, minlength=len(classes))
        last = np.zeros(len(classes), dtype=np.int64)
        np.maximum.at(last, which, np.arange(len(which)))   # where each class is listed last
        best = np.lexsort((-last, -score))[0]
        self.CLASS_OUTPUT[...] = classes[best]
