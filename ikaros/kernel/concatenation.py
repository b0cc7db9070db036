"""How several connections into one input are put together, and in which order a delay
window gives its slots: the ``concatenation`` setting (docs/language.md, "Several
connections into one input").

- ``reversed`` (Ikaros 2's, the default in an Ikaros 2 file): laid end to end with the
  connection declared last first; a window gives its slots in the reverse of the listed
  order (``1:3``: the longest delay first). Ikaros 2 makes one connection per delay and puts
  each new connection first.
- ``overlay`` (Ikaros 3's, the default in an Ikaros 3 file): every connection without a
  target position writes from element 0, a later one over an earlier one, and the input
  takes the size of the largest; only a ``flatten`` input lays them end to end (in
  declaration order). Windows give their slots in the listed order.
- ``declared``: laid end to end in declaration order, windows in the listed order (this
  project's rule before it followed Ikaros 2).

A module element sets it for one input (``INPUT.concatenation``) or for all its inputs, a
group port on its ``<input>`` element, and a group (or the top group, or a load-time
override) for everything inside it; the nearest setting wins.
"""
from __future__ import annotations

import numpy as np

from ..language.diagnostics import warn_at
from .buffers import Run

CONCATENATIONS = ("reversed", "overlay", "declared")
DEFAULT = {"2": "reversed", "3": "overlay"}
ATTRIBUTE = "concatenation"


def check_value(value: str) -> str:
    """A setting as written, checked; raises ValueError naming the allowed values."""
    text = value.strip().lower()
    if text not in CONCATENATIONS:
        raise ValueError(f'{ATTRIBUTE}="{value}" must be one of '
                         f'{", ".join(CONCATENATIONS)}')
    return text


def window_order(delays: list[int], concatenation: str) -> list[int]:
    """The delays of a connection in the order of its window's slots."""
    if concatenation == "reversed" and len(delays) > 1:
        return delays[::-1]
    return delays


def uncover(runs: list[Run], size: int) -> None:
    """Runs (in declaration order) that overlay one another (Ikaros 3): each element is kept
    only in the run that writes it last, so the copies may run in any order. Ikaros 3 copies
    the delayed connections at the end of a tick and a zero-delay connection just before its
    target ticks (KERNEL §3.2), so a zero-delay connection wins over delayed ones, and among
    the rest the later declared wins. A run left with nothing keeps its place (it still
    orders the schedule and counts for the start-up steps)."""
    if sum(len(r.dst_index) for r in runs) <= size:
        return
    last = sorted(range(len(runs)), key=lambda k: (runs[k].delay == 0 and not runs[k].window,
                                                    k))
    taken = np.zeros(size, dtype=bool)
    for k in reversed(last):
        run = runs[k]
        dst = np.asarray(run.dst_index)
        free = ~taken[dst]
        taken[dst] = True
        if not free.all():
            run.dst_index = dst[free]
            run.src_index = np.asarray(run.src_index)[free]


def warn_shared_zero_delay(runs: list[Run]) -> None:
    """Ikaros 2 gives an input fed over ``delay="0"`` its source's memory, so it refuses a
    zero-delay connection into an input that has another connection; here the input copies.
    Warn at the zero-delay connection (``--strict`` refuses it)."""
    if len(runs) < 2:
        return
    for run in runs:
        if run.delay == 0:
            warn_at(run.node, f'{run.target.path} is fed over delay 0 and by another '
                              f'connection or delay; Ikaros 2 refuses this (a zero-delay '
                              f'input is its source\'s memory there), here the input copies')
            return
