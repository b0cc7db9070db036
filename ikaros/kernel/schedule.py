"""The execution order: topological over zero-delay connections, declaration order for ties."""
from __future__ import annotations

import heapq


def schedule(modules: list, edges: dict) -> list:
    """Order modules so that every zero-delay source runs before its target.

    ``modules`` carry an ``order`` (declaration order); ``edges`` maps (source, target) to the
    connection element that joins them. A zero-delay cycle is an error that names every
    module in it and the line of one of its connections.
    """
    if all(src.order < dst.order for (src, dst) in edges) and \
            all(a.order < b.order for a, b in zip(modules, modules[1:])):
        return list(modules)     # declared in an order that works: the same result, at once
    successors = {m: [] for m in modules}
    indegree = {m: 0 for m in modules}
    for (src, dst) in edges:
        successors[src].append(dst)
        indegree[dst] += 1
    ready = [(m.order, id(m), m) for m in modules if indegree[m] == 0]
    heapq.heapify(ready)
    ordered = []
    while ready:
        _, _, m = heapq.heappop(ready)
        ordered.append(m)
        for n in successors[m]:
            indegree[n] -= 1
            if indegree[n] == 0:
                heapq.heappush(ready, (n.order, id(n), n))
    if len(ordered) != len(modules):
        cycle = _find_cycle([m for m in modules if indegree[m] > 0], successors)
        node = edges[(cycle[0], cycle[1 % len(cycle)])]
        names = " -> ".join(m.path for m in cycle + cycle[:1])
        raise node.error(f"zero-delay cycle: {names}; give one of these connections a delay "
                         f"of 1 or more")
    return ordered


def _find_cycle(remaining: list, successors: dict) -> list:
    """One cycle among the modules that could not be ordered. Each of them still has an
    unordered predecessor, so walking predecessors must come back to a module seen before."""
    left = set(remaining)
    predecessors = {m: [] for m in remaining}
    for m in remaining:
        for n in successors[m]:
            if n in left:
                predecessors[n].append(m)
    path, index = [], {}
    m = min(remaining, key=lambda m: m.order)
    while m not in index:
        index[m] = len(path)
        path.append(m)
        m = min(predecessors[m], key=lambda n: n.order)
    cycle = path[index[m]:]
    cycle.reverse()
    return cycle


def thread_groups(ordered: list, edges: dict) -> list[list]:
    """Modules joined by zero-delay connections (weakly connected), each in schedule order."""
    parent = {m: m for m in ordered}

    def find(m):
        while parent[m] is not m:
            parent[m] = parent[parent[m]]
            m = parent[m]
        return m

    for (a, b) in edges:
        parent[find(a)] = find(b)
    groups: dict = {}
    for m in ordered:
        groups.setdefault(find(m), []).append(m)
    return list(groups.values())

