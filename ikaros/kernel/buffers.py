"""Buffers (module inputs and outputs, group ports) and the links between them."""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..language.node import Node
from ..module import InputPart
from .gating import arrival_tick


class Buffer:
    """A module output, a module input, or a group port (an Ikaros 3 group input/output).

    Inputs and ports are filled by incoming links; outputs are written by their module.
    """

    __slots__ = ("kind", "owner", "name", "optional", "flatten", "stack", "fixed", "node",
                 "shape", "incoming", "outgoing", "array", "offset", "dynamic",
                 "dynamic_array", "use_label", "alias", "concatenation")

    def __init__(self, kind: str, owner, name: str, *, optional: bool = False,
                 flatten: bool = False, stack: bool = False, fixed: str | None = None,
                 node: Node | None = None, use_label: bool = False,
                 concatenation: str = "declared"):
        self.kind = kind                  # "output", "input" or "port"
        self.owner = owner                # a ModuleInstance or a Group
        self.name = name
        self.optional = optional
        self.flatten = flatten
        self.stack = stack
        self.fixed = fixed                # a fixed shape expression for an input
        self.use_label = use_label        # an input that takes its connection's label
        # how several connections are put together (kernel/concatenation.py)
        self.concatenation = concatenation
        self.node = node
        self.shape: tuple | None = None
        # () until the first link (most buffers have one or none; fewer objects to build
        # and for the garbage collector to trace): see ``link``
        self.incoming: list[Link] | tuple = ()
        self.outgoing: list[Link] | tuple = ()
        self.array: np.ndarray | None = None
        self.offset: int | None = None    # where ``array`` starts in the arena, in elements
        # A dynamic output, or an input fed by one: ``shape`` is then the capacity, and in
        # the network ``dynamic_array`` what the module sees and ``array`` its storage,
        # outside the arena.
        self.dynamic = False
        self.dynamic_array = None
        # an output that is a view of another output of its module (Ikaros 3 alias):
        # (that output's buffer, the indices), set when it is sized
        self.alias: tuple | None = None

    @staticmethod
    def link(link: "Link") -> None:
        """Add a link to its source's outgoing and its target's incoming links."""
        src, dst = link.source, link.target
        if src.outgoing:
            src.outgoing.append(link)
        else:
            src.outgoing = [link]
        if dst.incoming:
            dst.incoming.append(link)
        else:
            dst.incoming = [link]

    @property
    def path(self) -> str:
        owner = self.owner.path
        return f"{owner}.{self.name}" if owner else self.name

    @property
    def size(self) -> int:
        return math.prod(self.shape) if self.shape is not None else 0

    def parts(self) -> list[InputPart]:
        """What each connection into this laid-out input brings, in declaration order
        (``Module.input_parts``)."""
        links = sorted(self.incoming, key=lambda lk: lk.order)
        return [InputPart(_label(lk), lk.source.path, tuple(lk.piece_shape), lk.dst_index,
                          arrival_tick(lk.source.owner, lk.delays))
                for lk in links]

    def label(self) -> str | None:
        """The label of an input that uses labels: that of its one labelled connection
        (``Module.input_label``)."""
        if not self.use_label:
            return None
        named = [label for label in map(_label, self.incoming) if label is not None]
        return named[0] if len(named) == 1 else None

    def __repr__(self):
        return f"<{self.kind} {self.path} {self.shape}>"


@dataclass(eq=False, slots=True)
class Link:
    """One connection between two buffers, after group aliases are followed.

    ``src_sel`` is None, ("offset", start, count) or ("selector", dims); ``dst_sel`` is None,
    ("offset", start) or ("selector", dims).
    """
    source: Buffer
    target: Buffer
    delays: list[int]
    node: Node
    order: int
    src_sel: tuple | None = None
    dst_sel: tuple | None = None
    label: str | None = None        # the connection's ``label`` (Ikaros 3)
    # Set by the layout: flat source indices of one lane, and flat target indices of all
    # lanes (lane-major).
    piece_shape: tuple = ()
    src_index: np.ndarray | None = None
    dst_index: np.ndarray | None = None

    @property
    def window(self) -> bool:
        return len(self.delays) > 1

    def describe(self) -> str:
        d = ",".join(map(str, self.delays))
        return f"{self.source.path} -> {self.target.path} (delay {d})"


@dataclass(eq=False, slots=True)
class Run:
    """Resolved data flow into a module input: elements ``src_index`` of module output
    ``source`` at ``delay`` go to elements ``dst_index`` of the input."""
    source: Buffer
    target: Buffer
    delay: int
    src_index: np.ndarray
    dst_index: np.ndarray
    node: Node
    window: bool = False
    links: list = field(default_factory=list)

    @property
    def whole(self) -> bool:
        """Whether the run copies the whole source onto the whole target, in order."""
        n = self.source.size
        return (n == self.target.size and _identity(self.src_index, n)
                and _identity(self.dst_index, n))


def _label(link: Link) -> str | None:
    """A connection's label; one without a label that reads a group port takes the label of
    the one connection into that port."""
    seen = set()
    while link.label is None and link.source.kind == "port" and \
            len(link.source.incoming) == 1 and link.source not in seen:
        seen.add(link.source)
        link = link.source.incoming[0]
    return link.label


def _identity(index, n: int) -> bool:
    """Whether an element map is 0, 1, ..., n-1."""
    if isinstance(index, range):
        return index == range(n)
    return len(index) == n and bool(np.array_equal(index, np.arange(n)))


def alias_view(array: np.ndarray, index: tuple, shape: tuple) -> tuple[np.ndarray, int]:
    """The part of a (C-contiguous) output array that an alias with these indices views,
    shaped ``shape``, and where it starts in the array, in elements."""
    start = int(np.ravel_multi_index(index + (0,) * (array.ndim - len(index)),
                                     array.shape)) if index else 0
    count = int(np.prod(shape))
    return array.reshape(-1)[start:start + count].reshape(shape), start
