"""Dynamic outputs in the kernel (Ikaros 3 ``dynamic="yes"``): the connections they may
feed, and their delays.

A dynamic output is sized by its capacity; its array (the whole capacity) lives outside the
arena, so the compiled tick and fusion leave the modules that touch one to Python, and
fixed-size buffers pay nothing for the feature. Only whole, single-delay connections may
leave one, and an input it feeds takes no other connection: that input is a DynamicArray
too, the output's own for delay 0, else a copy that takes the shape and values the output
had ``delay`` ticks before.
"""
from __future__ import annotations

from ..dynamic import DynamicArray
from ..errors import ModelError
from .buffers import Buffer, Link


def unresolved_capacity(inst, buf: Buffer) -> str:
    """The error for a dynamic output whose capacity never resolved."""
    rule = inst.module._ik_outputs[buf.name].rule_text()
    return (f'the capacity of dynamic output "{buf.name}" of {inst.path} could not be '
            f'resolved ({rule}); check that the inputs it names are connected and sized')


def check_dynamic_connections(outputs) -> None:
    """Refuse the connections a dynamic output cannot feed (following group ports), and
    mark the inputs it feeds dynamic."""
    for out in outputs:
        if out.dynamic:
            if out.owner.asynchronous:
                raise out.owner.node.error(f"{out.path} is a dynamic output, which an "
                                           f'asynchronous module (async="yes") cannot have')
            for link in out.outgoing:
                _follow(out, link)


def _error(link: Link, message: str) -> ModelError:
    return link.node.error(f"{message} ({link.describe()})")


def _follow(out: Buffer, link: Link) -> None:
    if link.src_sel is not None or link.dst_sel is not None:
        raise _error(link, f"{out.path} is dynamic: Dynamic outputs only support whole-matrix "
                           f"connections (no selectors or offsets)")
    if len(link.delays) > 1:
        raise _error(link, f"{out.path} is dynamic: dynamic outputs support only a single "
                           f"whole-matrix delay, not a delay window")
    target = link.target
    if len(target.incoming) > 1 or target.stack or target.flatten or target.fixed:
        raise _error(link, f"{target.path} is fed by the dynamic output {out.path}, so it "
                           f"can take no other connection and cannot be stacked, flattened "
                           f"or of a fixed size")
    target.dynamic = True
    if target.kind == "port":
        for onward in target.outgoing:
            _follow(out, onward)
    elif target.owner.asynchronous:
        raise _error(link, f"{target.path} is fed by the dynamic output {out.path}, which "
                           f'an asynchronous module (async="yes") cannot take')


class DynamicRing:
    """The history of a dynamic output beyond its current value, shapes included (as
    memory.Ring for fixed outputs): ``row(d)`` is its value from d >= 2 ticks before the
    coming tick, read before ``push``."""

    def __init__(self, output: DynamicArray, depth: int):
        self.output = output
        self.depth = depth
        self.rows = [DynamicArray(output.capacity) for _ in range(depth)]
        self.pos = depth - 1

    def push(self) -> None:
        self.pos = (self.pos + 1) % self.depth
        self.rows[self.pos].assign(self.output)

    def row(self, delay: int) -> DynamicArray:
        return self.rows[(self.pos - (delay - 2)) % self.depth]


def delayed_copy(target: DynamicArray, source: DynamicArray, delay: int,
                 ring: DynamicRing | None):
    """The copy, at the start of a tick, of a dynamic output's value from ``delay`` >= 1
    ticks before into the input it feeds."""
    if delay == 1:
        return lambda: target.assign(source)
    return lambda: target.assign(ring.row(delay))
