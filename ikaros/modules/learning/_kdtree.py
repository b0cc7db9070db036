"""The order of the examples in the k-d tree of Ikaros 2's KNN."""
import math

import numpy as np


class KDTree:
    """The shape of a k-d tree grown by insertion: a new point goes down from the root, to
    the left where its element of the level's dimension (the depth modulo the number of
    dimensions) is smaller than the node's, else to the right. ``key(i)`` orders the points
    as the tree's pre-order does (a node, then its left subtree, then its right).

    With ``rebuild`` (minimum size, ratio), when a tree of at least the minimum size gets a
    point deeper than ratio × log2(size), the highest subtree on the new point's path whose
    larger half holds more than 1 / (1 + 1 / ratio) of it (a scapegoat) is rebuilt
    balanced: each node the median of its points along the level's dimension (the first of
    equal ones, so that the smaller points are on its left). Rebuilding only that subtree
    keeps insertion cheap on average, even for points that arrive sorted."""

    def __init__(self, rebuild: tuple[int, float] | None = None):
        self._children: list[list[int]] = []     # [left, right] of each point; -1: none
        self._paths: list[tuple] = []           # the turns from the root to each point
        self._sizes: list[int] = []             # the number of points of each subtree
        self._root = -1
        self._rebuild = rebuild
        self._next_check = 0        # no rebuild before this size (equal points defeat it)

    def insert(self, points: np.ndarray, index: int) -> None:
        """Add point ``index`` of ``points`` (the rows before it are in the tree)."""
        self._children.append([-1, -1])
        self._sizes.append(1)
        if self._root < 0:
            self._root = index
            self._paths.append(())
            return
        x, node, path, nodes = points[index], self._root, [], []
        while True:
            nodes.append(node)
            self._sizes[node] += 1
            side = 0 if x[len(path) % points.shape[1]] < points[node, len(path) % points.shape[1]] \
                else 1
            path.append(side)
            if self._children[node][side] < 0:
                self._children[node][side] = index
                self._paths.append(tuple(path))
                break
            node = self._children[node][side]
        size = index + 1
        if self._rebuild and size >= max(self._rebuild[0], self._next_check) and \
                len(path) > self._rebuild[1] * math.log2(size):
            share = 1 / (1 + 1 / self._rebuild[1])
            for depth, top in enumerate(nodes):
                larger = max(self._size(c) for c in self._children[top])
                if larger > share * self._sizes[top]:
                    self._balance(points, top, depth)
                    break
            if len(self._paths[index]) > self._rebuild[1] * math.log2(size):
                self._next_check = 2 * size         # equal points: rebuilding cannot help

    def _size(self, node: int) -> int:
        return self._sizes[node] if node >= 0 else 0

    def _members(self, top: int) -> np.ndarray:
        found, work = [], [top]
        while work:
            node = work.pop()
            found.append(node)
            work.extend(c for c in self._children[node] if c >= 0)
        return np.array(found, dtype=np.int64)

    def _balance(self, points: np.ndarray, top: int, depth: int) -> None:
        """Rebuild the subtree of ``top`` (at ``depth``) balanced, in its place."""
        dims = points.shape[1]
        prefix = self._paths[top]
        parent_slot = None
        if depth > 0:
            parent = self._root
            for turn in prefix[:-1]:
                parent = self._children[parent][turn]
            parent_slot = (parent, prefix[-1])
        work = [(self._members(top), depth, prefix, parent_slot)]
        while work:
            members, level, path, slot = work.pop()
            values = points[members, level % dims]
            sort = np.argsort(values, kind="stable")
            order, sorted_values = members[sort], values[sort]
            at = int(np.searchsorted(sorted_values, sorted_values[len(order) // 2]))
            node = int(order[at])
            self._paths[node] = path
            self._children[node] = [-1, -1]
            self._sizes[node] = len(order)
            if slot is None:
                self._root = node
            else:
                self._children[slot[0]][slot[1]] = node
            if at > 0:
                work.append((order[:at], level + 1, path + (0,), (node, 0)))
            if at + 1 < len(order):
                work.append((order[at + 1:], level + 1, path + (1,), (node, 1)))

    def key(self, index: int) -> tuple:
        """The sort key of a point in pre-order: its turns from the root (a path sorts
        before the paths that extend it, left turns before right)."""
        return self._paths[index]
