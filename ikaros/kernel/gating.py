"""Start gating (Ikaros 3 ``module_start`` and ``start_tick``): each module's start-up steps
and the first tick it runs.

A module's start-up steps are the first tick on which data that began at a module without
inputs reaches its first input (``first``) and all its inputs (``all``). A module without
connected inputs has steps (0, 0); a connection of delay d from a module with steps (f, a)
gives its target f + d for ``first`` and a + d for ``all``; a module takes the smallest
``first`` and the largest ``all`` over its incoming connections (a delay window counts
each of its delays). A step that no chain of connections from a module without inputs
reaches (``first``), or that waits on a loop (``all``), is None: a module started there
never runs.
"""
from __future__ import annotations

import collections
import heapq

MODULE_START = {"at_tick": "at_tick", "first_data": "first_data", "all_data": "all_data",
                "0": "at_tick", "1": "first_data", "2": "all_data"}


class StartSteps:
    """The start-up steps of a network's modules, computed when first asked for (most
    models never ask)."""

    def __init__(self, modules: list, runs: list):
        self._modules, self._runs = modules, runs
        self._steps: dict | None = None

    def of(self, module) -> tuple:
        """(first, all) of a module instance, or of its Module object."""
        if self._steps is None:
            steps = start_steps(self._modules, self._runs)
            steps.update({inst.module: s for inst, s in steps.items()})
            self._steps = steps
        return self._steps[module]


def start_steps(modules: list, runs: list) -> dict:
    """{module: (first, all)} for every module, from the runs between module outputs and
    inputs (runs.Run: source, target, delay)."""
    feeds = collections.defaultdict(list)       # module -> [(target module, delay)]
    fed = collections.defaultdict(list)         # module -> [(source module, delay)]
    for run in runs:
        feeds[run.source.owner].append((run.target.owner, run.delay))
        fed[run.target.owner].append((run.source.owner, run.delay))
    first = _shortest(modules, feeds, fed)
    every = _longest(modules, feeds, fed)
    return {m: (first.get(m), every.get(m)) for m in modules}


def _shortest(modules, feeds, fed) -> dict:
    """The smallest sum of delays from a module without inputs (Dijkstra)."""
    best = {m: 0 for m in modules if not fed[m]}
    heap = [(0, i, m) for i, m in enumerate(modules) if not fed[m]]
    order = {m: i for i, m in enumerate(modules)}
    done = set()
    while heap:
        step, _, m = heapq.heappop(heap)
        if m in done:
            continue
        done.add(m)
        for target, delay in feeds[m]:
            if step + delay < best.get(target, step + delay + 1):
                best[target] = step + delay
                heapq.heappush(heap, (step + delay, order[target], target))
    return best


def _longest(modules, feeds, fed) -> dict:
    """The largest sum of delays over all paths from modules without inputs, for the
    modules that no loop feeds (in topological order)."""
    waiting = {m: len(fed[m]) for m in modules}
    ready = collections.deque(m for m in modules if not waiting[m])
    step = {m: 0 for m in ready}
    while ready:
        m = ready.popleft()
        for target, delay in feeds[m]:
            step[target] = max(step.get(target, 0), step[m] + delay)
            waiting[target] -= 1
            if not waiting[target]:
                ready.append(target)
    return {m: s for m, s in step.items() if not waiting[m]}


def arrival_tick(source, delays) -> int:
    """The first tick on which a connection from ``source`` (a module instance or a group
    port) with ``delays`` brings data that began at modules without inputs: the source's
    ``all`` step (or its ``first`` when a loop feeds it; 0 when nothing does) plus the
    connection's largest delay."""
    module = getattr(source, "module", None)
    steps = getattr(module, "_ik_start_steps", None)
    first, every = steps.of(module) if steps is not None else (0, 0)
    base = every if every is not None else first if first is not None else 0
    return base + max(delays, default=0)


def first_tick(inst, steps: StartSteps) -> int | None:
    """The first tick a module runs: ``start_tick``, or later its start-up step for
    ``first_data`` and ``all_data``; None for never."""
    if inst.module_start == "at_tick":
        return inst.start_tick
    step = steps.of(inst)[0 if inst.module_start == "first_data" else 1]
    return None if step is None else max(step, inst.start_tick)


def gated(step, inst, clock):
    """A module's tick (``step``) that runs only from its first tick on: ``step`` itself
    when that is tick 0, nothing when it never runs."""
    start = inst.first_tick
    if start == 0:
        return step
    if start is None:
        return lambda: None

    def from_start():
        if clock.tick >= start:
            step()
    return from_start
