"""Recording a run in memory: ``net.run(ticks=..., record=[...])``."""
from __future__ import annotations

import numpy as np

from .reading import to_dataset
from .signals import module_parameters, select_outputs


def run_recorded(net, ticks: int | None, patterns: list[str] | str, every: int = 1,
                 real_time: bool = False):
    """Run ``ticks`` more ticks keeping the outputs matching ``patterns`` every ``every``-th
    tick; returns them as an xarray Dataset (as ``open_recording`` gives)."""
    if ticks is None:
        raise ValueError("run(record=...) needs ticks: the number of ticks to run")
    every = int(every)
    if every < 1:
        raise ValueError(f"every must be a whole number >= 1, not {every}")
    signals, index = select_outputs(net, None if patterns in ("*", ["*"]) else patterns)
    first = net.tick
    capacity = -(-int(ticks) // every)
    rows = np.zeros((capacity, index.size), np.float32)
    recorded = np.zeros(capacity, np.int64)
    n = 0

    def hook():
        nonlocal n
        tick = net.tick - 1
        if (tick - first) % every == 0 and n < capacity:
            np.take(net.arena.block, index, out=rows[n])
            recorded[n] = tick
            n += 1
    hooks = net.controller.tick_hooks
    hooks.append(hook)
    try:
        net.run(ticks=ticks, real_time=real_time)
    finally:
        hooks.remove(hook)
    parameters = module_parameters(net)
    attrs = {"model_file": net.filename or "", "top_group": net.top.name,
             "parameters": parameters, "every": every,
             "tick_duration": net.clock.tick_duration}
    return to_dataset(signals, rows, recorded[:n], recorded[:n] * net.clock.tick_duration,
                      attrs)
