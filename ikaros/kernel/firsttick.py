"""The first tick of an Ikaros 3 file (docs/language.md, "Dialect").

Ikaros 3 numbers its first tick 1 (time 1 × tick_duration), and its sources write in their
tick, not in init: what a module wrote in init never travels through a delay, so across a
delay-n connection the receiver reads zeros until n ticks have completed. Ikaros 2 numbers
the first tick 0 and delivers init values on it; that is the kernel's way of running, and an
Ikaros 3 file differs from it only on the first tick, which the function below puts right.
"""
from __future__ import annotations

from typing import Callable

import numpy as np

from .dynamic import DynamicRing
from .memory import Ring

FIRST_TICK = {"2": 0, "3": 1}     # the number of a network's first tick, by dialect


def empty_history(runs, shared, rings: list) -> Callable[[], None]:
    """A function to call on the first tick, right after the delayed copies and the pushes
    of the histories (``rings``: those pushed every tick): every input fed through a delay
    reads zeros (an input fed by a dynamic output, no rows), and each history's newest row
    (the value before the first tick) is zeros too."""
    targets, dynamic = [], []
    for run in runs:
        if run.delay == 0 or run.target in shared:
            continue
        if run.source.dynamic:
            dynamic.append(run.target.dynamic_array)
        else:
            targets.append((run.target.array.reshape(-1),
                            np.ascontiguousarray(run.dst_index, dtype=np.intp)))
    fixed = [ring for ring in rings if isinstance(ring, Ring)]
    dynamic_rings = [ring for ring in rings if isinstance(ring, DynamicRing)]

    def clear() -> None:
        for flat, index in targets:
            flat[index] = 0.0
        for target in dynamic:
            target.clear()
        for ring in fixed:
            ring.rows[ring.pos].fill(0.0)
        for ring in dynamic_rings:
            ring.rows[ring.pos].clear()
    return clear
