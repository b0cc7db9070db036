"""Buffer memory: one float32 arena for all buffers, history rings, and compiled copies."""
from __future__ import annotations

import math
from functools import partial

import numpy as np

ALIGN = 16    # elements (64 bytes), so every buffer starts on a cache line


class Arena:
    """Hands out views into one zero-filled float32 block, allocated once."""

    def __init__(self):
        self._shapes: list[tuple] = []
        self.offsets: list[int] = []          # where each request starts, in elements
        self.views: list[np.ndarray] = []     # each request's view of the block
        self.block: np.ndarray | None = None

    def request(self, shape: tuple) -> int:
        """Reserve room for an array; returns the number of the request, whose view and
        offset are ``views[k]`` and ``offsets[k]`` after ``allocate``."""
        self._shapes.append(shape)
        return len(self._shapes) - 1

    def planned_bytes(self) -> int:
        """The size the block will have, in bytes (before ``allocate``)."""
        return sum(-(-math.prod(shape) // ALIGN) * ALIGN for shape in self._shapes) * 4

    def allocate(self) -> None:
        offsets, total = self.offsets, 0
        sizes = [math.prod(shape) for shape in self._shapes]
        for n in sizes:
            offsets.append(total)
            total += -(-n // ALIGN) * ALIGN
        block = self.block = np.zeros(max(total, 1), dtype=np.float32)
        views = self.views
        for shape, n, start in zip(self._shapes, sizes, offsets):
            view = block[start:start + n]
            views.append(view if len(shape) == 1 else view.reshape(shape))

    @property
    def nbytes(self) -> int:
        return 0 if self.block is None else self.block.nbytes


class Ring:
    """The history of one output beyond its current value: row k of ``rows`` after ``push``
    holds older values; ``row(d)`` is the value from d ticks before the current one."""

    def __init__(self, output: np.ndarray, depth: int, arena: Arena):
        self.output = output.reshape(-1)
        self.depth = depth               # values kept: x(n-2) ... x(n-1-depth)
        self._arena = arena
        self._request = arena.request((depth, self.output.size))
        self.rows: list[np.ndarray] = []
        self.pos = 0

    def bind(self) -> None:
        block = self._arena.views[self._request]
        self.rows = [block[k] for k in range(self.depth)]
        self.pos = self.depth - 1

    def push(self) -> None:
        """Store the output's value (the previous tick's, before modules run)."""
        self.pos = (self.pos + 1) % self.depth
        np.copyto(self.rows[self.pos], self.output)

    def row(self, delay: int) -> np.ndarray:
        """Before ``push``: the value from ``delay`` >= 2 ticks before the coming tick."""
        return self.rows[(self.pos - (delay - 2)) % self.depth]


def _contiguous(index) -> slice | None:
    if len(index) == 0:
        return None
    if isinstance(index, range):
        return slice(index.start, index.stop) if index.step == 1 else None
    start = int(index[0])
    if np.array_equal(index, np.arange(start, start + len(index))):
        return slice(start, start + len(index))
    return None


def compile_copy(dst: np.ndarray, dst_index: np.ndarray, src: np.ndarray,
                 src_index: np.ndarray):
    """A no-argument function that copies src[src_index] to dst[dst_index] (flat indices);
    a plain slice copy when both sides are contiguous."""
    dst_flat, src_flat = dst.reshape(-1), src.reshape(-1)
    ds, ss = _contiguous(dst_index), _contiguous(src_index)
    if ds is not None and ss is not None:
        return partial(np.copyto, dst_flat[ds], src_flat[ss])
    scratch = np.zeros(len(src_index), dtype=np.float32)
    src_index = np.ascontiguousarray(src_index, dtype=np.intp)
    dst_index = np.ascontiguousarray(dst_index, dtype=np.intp)

    def copy():
        np.take(src_flat, src_index, out=scratch)
        dst_flat[dst_index] = scratch
    return copy


def compile_ring_copy(dst: np.ndarray, dst_index: np.ndarray, ring: Ring, delay: int,
                      src_index: np.ndarray):
    """Like compile_copy, reading the ring's value from ``delay`` ticks back."""
    copies = []
    for k in range(ring.depth):
        copies.append(compile_copy(dst, dst_index, ring.rows[k], src_index))
    depth, offset = ring.depth, delay - 2

    def copy():
        copies[(ring.pos - offset) % depth]()
    return copy


BULK_LIMIT = 256   # runs up to this many elements are gathered into one bulk copy


class BulkCopy:
    """Many small copies within one arena done as one gather and one scatter."""

    def __init__(self, block: np.ndarray):
        self.block = block
        self._src: list[int] = []       # flat arena indices, element by element
        self._dst: list[int] = []

    def accepts(self, dst: np.ndarray, src: np.ndarray, count: int) -> bool:
        """Whether a copy between these arrays can join (both in the arena, and small)."""
        return count <= BULK_LIMIT and dst.base is self.block and src.base is self.block

    def add(self, dst_offset: int, dst_index, src_offset: int, src_index) -> None:
        """Add a copy between arena buffers at these offsets (in elements)."""
        self._dst.extend(_shifted(dst_index, dst_offset))
        self._src.extend(_shifted(src_index, src_offset))

    def indices(self) -> tuple[np.ndarray, np.ndarray]:
        """The flat arena indices copied from and to, element by element."""
        return np.array(self._src, dtype=np.intp), np.array(self._dst, dtype=np.intp)

    def compile(self):
        """The copy as a no-argument function, or None when nothing was added."""
        if not self._src:
            return None
        src, dst = self.indices()
        scratch = np.zeros(len(src), dtype=np.float32)
        block = self.block

        def copy():
            np.take(block, src, out=scratch)
            block[dst] = scratch
        return copy


def _shifted(index, offset: int):
    """An element map moved by ``offset`` elements (a range stays a range)."""
    if isinstance(index, range):
        return range(index.start + offset, index.stop + offset, index.step)
    return (np.asarray(index, dtype=np.intp) + offset).tolist()
