"""KNN: a k-nearest-neighbour memory."""
import numpy as np

from ikaros.module import Input, Module, Output, Parameter

from ._kdtree import KDTree


class KNN(Module):
    """A k-nearest-neighbour memory, as Ikaros 2 has it (the class is not in Ikaros 3). On
    every tick where the first element of LEARN is above 0 (every tick when LEARN is
    unconnected) the pair T_INPUT -> T_OUTPUT is stored; then the k stored examples nearest
    to INPUT are looked up, and row i of INPUT_TABLE, OUTPUT_TABLE and DISTANCE_TABLE gives
    the i-th neighbour's input, its output and its distance to INPUT (``euclidian`` or
    ``manhattan``). While fewer than k examples are stored, the missing rows have distance
    -1 and zero inputs and outputs. With ``check_for_clones`` an example whose input is
    already stored is not stored again. Inputs of any shape are read flat.

    Ikaros 2 keeps the examples in a k-d tree (each new example goes down the tree, to the
    left where its element of the level's dimension, cycling through the dimensions, is
    smaller than the node's, else to the right) and computes as the golden files show: the
    squared euclidian distance is cut to a whole number before its square root is taken (a
    defect: examples closer than 1 are at distance 0, and 1.47 comes out as 1.41), and the
    neighbours are listed in the tree's order (a node before its left subtree, the left
    before the right), not nearest first. This class does the same by default; which k
    examples are chosen when more are stored (here the k nearest by the cut distance, ties
    in the tree's order), manhattan distances (here not cut) and how Ikaros 2 rebalances its
    tree are this project's reading: no reference shows them. Here, with ``auto_rebuild``, a
    tree of at least ``minimum_tree_size_for_rebuild`` examples whose newest example lies
    deeper than ``unbalanced_tree_size_ratio_limit`` × log2(examples) is rebuilt balanced,
    each node the median of its examples along the level's dimension. ``exact_distances="yes"`` (this project's) gives exact distances, nearest
    first (the earlier stored first on ties). The command ``reset`` forgets all examples."""

    k = Parameter(5, "how many neighbours to look up", type="int")
    distance_type = Parameter("euclidian", "euclidian: the square root of the sum of squared "
                              "differences; manhattan: the sum of absolute differences",
                              options="euclidian/manhattan")
    exact_distances = Parameter(False, "no: as Ikaros 2, squared distances cut to whole "
                                "numbers and neighbours in the k-d tree's order; yes: exact "
                                "distances, nearest first")
    auto_rebuild = Parameter(True, "rebuild the k-d tree balanced when it grows unbalanced "
                             "(it sets the neighbours' order)")
    minimum_tree_size_for_rebuild = Parameter(100, "the fewest examples of a tree that is "
                                              "rebuilt", type="int")
    unbalanced_tree_size_ratio_limit = Parameter(2.4, "the tree is rebuilt when an example "
                                                 "lies deeper than this times log2(examples)")
    verbose = Parameter(False, "print the number of stored examples when one is added")
    check_for_clones = Parameter(False, "do not store an example whose input is already "
                                 "stored")
    INPUT = Input("the point whose neighbours are looked up")
    T_INPUT = Input("the input of an example to store")
    T_OUTPUT = Input("the output (class value) of the example to store")
    LEARN = Input("T_INPUT -> T_OUTPUT is stored on ticks where its first element is above 0; "
                  "unconnected: on every tick", optional=True)
    INPUT_TABLE = Output("the inputs of the k nearest examples, one row each")
    OUTPUT_TABLE = Output("the outputs of the k nearest examples, one row each")
    DISTANCE_TABLE = Output("the distances of the k nearest examples to INPUT; -1 where there "
                            "is no example")

    def set_sizes(self):
        n, t = self.input_shape("INPUT"), self.input_shape("T_OUTPUT")
        k = max(1, self.k)
        if n is not None:
            self.set_output_shape("INPUT_TABLE", (k, int(np.prod(n))))
        if t is not None:
            self.set_output_shape("OUTPUT_TABLE", (k, int(np.prod(t))))
        self.set_output_shape("DISTANCE_TABLE", (k,))

    def init(self):
        if self.k < 1:
            raise ValueError("k must be at least 1")
        self._n = self.INPUT.size
        if self.T_INPUT.size != self._n:
            raise ValueError(f"T_INPUT has {self.T_INPUT.size} elements but INPUT has "
                             f"{self._n}")
        self._c = self.T_OUTPUT.size
        self._x = np.zeros((16, self._n), np.float32)   # stored inputs (first _count rows)
        self._y = np.zeros((16, self._c), np.float32)   # stored outputs
        self._count = 0
        self._tree = self._new_tree()
        self.DISTANCE_TABLE.fill(-1)

    def _new_tree(self):
        return KDTree((max(1, self.minimum_tree_size_for_rebuild),
                       self.unbalanced_tree_size_ratio_limit) if self.auto_rebuild else None)

    def command(self, name, x=0, y=0, value=None):
        if name == "reset":
            self._count = 0
            self._tree = self._new_tree()

    def _store(self, x, y):
        stored = self._x[:self._count]
        if self.check_for_clones and self._count and np.any(np.all(stored == x, axis=1)):
            return
        if self._count == len(self._x):
            self._x = np.concatenate([self._x, np.zeros_like(self._x)])
            self._y = np.concatenate([self._y, np.zeros_like(self._y)])
        self._x[self._count] = x
        self._y[self._count] = y
        self._tree.insert(self._x, self._count)
        self._count += 1
        if self.verbose:
            self.print(f"{self._count} examples stored")

    def tick(self):
        if self.LEARN is None or self.LEARN.reshape(-1)[0] > 0:
            self._store(self.T_INPUT.reshape(-1), self.T_OUTPUT.reshape(-1))
        k, count = self.DISTANCE_TABLE.size, self._count
        found = min(k, count)
        if found:
            diff = self._x[:count] - self.INPUT.reshape(1, -1)
            exact = self.exact_distances
            if self.distance_type == "manhattan":
                dist = np.abs(diff).sum(axis=1)
            else:
                squared = np.einsum("ij,ij->i", diff, diff)
                dist = np.sqrt(squared if exact else np.floor(squared))
            if found < count:
                nearest = np.argpartition(dist, found - 1)[:found]
                # the whole tie group at the boundary takes part
                nearest = np.flatnonzero(dist <= dist[nearest].max())
            else:
                nearest = np.arange(count)
            if exact:                       # nearest first; ties: the earlier stored
                nearest = nearest[np.lexsort((nearest, dist[nearest]))][:found]
            else:                           # the nearest, in the tree's order
                key = self._tree.key
                nearest = sorted(nearest, key=lambda i: (dist[i], key(i)))[:found]
                nearest = np.array(sorted(nearest, key=key), dtype=np.int64)
            self.INPUT_TABLE[:found] = self._x[nearest]
            self.OUTPUT_TABLE[:found] = self._y[nearest]
            self.DISTANCE_TABLE[:found] = dist[nearest]
        self.INPUT_TABLE[found:] = 0
        self.OUTPUT_TABLE[found:] = 0
        self.DISTANCE_TABLE[found:] = -1
