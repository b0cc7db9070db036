"""Where each connection's data lands: the shape of inputs and ports, and the element maps
from module outputs to module inputs (through group ports).

An element map is a NumPy index array, or a ``range`` when it is contiguous (most are), so a
connection of a million-element image costs no memory for its map.
"""
from __future__ import annotations

import math
import numpy as np

from ..errors import ModelError
from ..language.values import selector_indices
from ..limits import max_elements
from .buffers import Buffer, Link, Run
from .concatenation import uncover


def _link_error(link: Link, message: str) -> ModelError:
    return link.node.error(f"{message} ({link.describe()})")


def _piece(link: Link) -> None:
    """The source elements one lane of a link reads, and their shape."""
    shape = link.source.shape
    size = math.prod(shape)
    sel = link.src_sel
    if sel is None:
        link.src_index = range(size)
        link.piece_shape = tuple(shape)
    elif sel[0] == "offset":
        start, count = sel[1], sel[2]
        if count is None:
            count = size - start
        if start < 0 or count < 0 or start + count > size:
            raise _link_error(link, f"sourceoffset {start} and size {count} reach outside the "
                                    f"source, which has {size} elements")
        link.src_index = range(start, start + count)
        link.piece_shape = (count,)
    else:
        dims = sel[1]
        if len(dims) > len(shape):
            raise _link_error(link, f"Cannot fill a rank-{len(dims)} range from a "
                                    f"rank-{len(shape)} range")
        dims = list(dims) + [("all",)] * (len(shape) - len(dims))
        lists = []
        for dim, extent in zip(dims, shape):
            if _reaches_past(dim, extent):
                raise _link_error(link, f"the source selector is outside its output bounds "
                                        f"(shape {shape})")
            idx = selector_indices(dim, extent)
            if any(i < 0 or i >= extent for i in idx):
                raise _link_error(link, f"the source selector is outside its output bounds "
                                        f"(shape {shape})")
            lists.append(idx)
        if len(lists) == 1:
            link.src_index = _index_map(lists[0])
        else:
            grids = np.meshgrid(*[np.array(i, dtype=np.intp) for i in lists], indexing="ij")
            link.src_index = np.ravel_multi_index([g.ravel() for g in grids], shape) \
                if all(len(i) for i in lists) else np.zeros((0,), dtype=np.intp)
        # Dimensions picked by a single index are dropped; one element is still a vector.
        link.piece_shape = tuple(len(i) for d, i in zip(dims, lists) if d[0] != "index") \
            or (1,)
    if link.window:
        link.piece_shape = (len(link.delays),) + link.piece_shape


def _reaches_past(dim: tuple, extent: int) -> bool:
    """Whether a selector dimension picks an index at or beyond ``extent`` (checked before
    its index list is made, which may be huge)."""
    if dim[0] == "index":
        return dim[1] >= extent
    if dim[0] != "range" or dim[2] <= dim[1]:
        return False
    _, a, b, step = dim
    return a + (b - 1 - a) // abs(step) * abs(step) >= extent


def _index_map(indices: list[int]):
    """A list of flat indices as an element map: a range when it is one."""
    if indices and indices == list(range(indices[0], indices[-1] + 1)):
        return range(indices[0], indices[-1] + 1)
    return np.array(indices, dtype=np.intp)


def _highest(index) -> int:
    return index[-1] if isinstance(index, range) else int(np.max(index))


def layout(buffer: Buffer, fixed_shape: tuple | None = None) -> None:
    """Size an input or port from its incoming links and give each link its target indices.

    A single whole connection keeps its shape. Several whole connections (or one into a
    ``flatten`` input) are laid end to end as a vector, in the order the buffer's
    ``concatenation`` says (kernel/concatenation.py); with ``overlay`` (Ikaros 3) each one
    writes from element 0 unless the input is ``flatten``. ``stack`` adds a leading axis
    with one slice per connection. Connections with ``targetoffset`` or a target selector
    write where they say.
    """
    links = buffer.incoming
    if len(links) == 1:
        link = links[0]
        if (link.src_sel is None and link.dst_sel is None and fixed_shape is None
                and not buffer.stack and not buffer.flatten and len(link.delays) == 1):
            # the common case: one whole connection, which keeps its shape
            shape = tuple(link.source.shape)
            link.src_index = link.dst_index = range(math.prod(shape))
            link.piece_shape = buffer.shape = shape
            return
    else:
        links = sorted(links, key=lambda lk: lk.order)
    for link in links:
        _piece(link)
    overlay = buffer.concatenation == "overlay" and not (buffer.flatten or buffer.stack)
    placed = [lk for lk in links if lk.dst_sel is not None]
    if placed and len(placed) != len(links) and not overlay:
        raise _link_error(placed[0], f"connections into {buffer.path} mix explicit target "
                                     f"positions with end-to-end placement")
    if placed or (overlay and len(links) > 1):
        shape = _place_explicitly(buffer, links, fixed_shape)
    elif buffer.stack:
        shape = _stack(buffer, links)
    elif buffer.flatten or len(links) > 1:
        if buffer.concatenation == "reversed":
            links = links[::-1]
        offset = 0
        for link in links:
            n = math.prod(link.piece_shape)
            link.dst_index = range(offset, offset + n)
            offset += n
        shape = (offset,)
    else:
        link = links[0]
        link.dst_index = range(math.prod(link.piece_shape))
        shape = link.piece_shape
    if fixed_shape is not None:
        total = math.prod(fixed_shape)
        for link in links:
            if len(link.dst_index) and _highest(link.dst_index) >= total:
                raise _link_error(link, f'writes outside fixed size of input "{buffer.name}" '
                                        f"{fixed_shape}")
        shape = tuple(fixed_shape)
    buffer.shape = tuple(int(s) for s in shape)


def _stack(buffer: Buffer, links: list[Link]) -> tuple:
    ranks = {len(lk.piece_shape) for lk in links}
    if len(ranks) != 1:
        raise _link_error(links[-1], f"stacked input {buffer.path} gets connections of "
                                     f"different ranks")
    extents = tuple(max(lk.piece_shape[d] for lk in links) for d in range(ranks.pop()))
    shape = (len(links),) + extents
    for k, link in enumerate(links):
        grids = np.meshgrid(*[np.arange(n) for n in link.piece_shape], indexing="ij")
        coords = [np.full(grids[0].size if grids else 1, k)] + [g.ravel() for g in grids]
        link.dst_index = np.ravel_multi_index(coords, shape)
    return shape


def _target(link: Link, offsets: bool, rank: int) -> tuple:
    """Where a link writes: its ``targetoffset`` or target selector; a whole connection
    (into an overlaid input) from element 0, a piece of lower rank than ``rank`` in the
    first row (the reference does not say what Ikaros 3 does with one)."""
    if link.dst_sel is not None:
        return link.dst_sel
    if offsets:
        return ("offset", 0)
    if link.window:
        return ("selector", [("range", 0, n, 1) for n in link.piece_shape[1:]])
    ones = [("range", 0, 1, 1)] * (rank - len(link.piece_shape))
    return ("selector", ones + [("range", 0, n, 1) for n in link.piece_shape])


def _place_explicitly(buffer: Buffer, links: list[Link], fixed_shape) -> tuple:
    offsets = [lk for lk in links if lk.dst_sel is not None and lk.dst_sel[0] == "offset"]
    if offsets and any(lk.dst_sel is not None and lk.dst_sel[0] != "offset" for lk in links):
        raise _link_error(links[0], f"connections into {buffer.path} mix targetoffset with "
                                    f"target selectors")
    if offsets:
        end = 0
        for link in links:
            n = math.prod(link.piece_shape)
            start = _target(link, True, 0)[1]
            if start < 0:
                raise _link_error(link, "targetoffset must not be negative")
            link.dst_index = range(start, start + n)
            end = max(end, start + n)
        return (end,)
    whole_rank = max(len(lk.piece_shape) for lk in links)
    rank = None
    coords_per_link = []
    for link in links:
        dims = list(_target(link, False, whole_rank)[1])
        piece = list(link.piece_shape)
        if link.window:             # the window's axis leads, before the selected ones
            dims = [("range", 0, len(link.delays), 1)] + dims
            piece = piece[1:]
        lists, extents = [], []
        holes = [i for i, d in enumerate(dims) if d[0] == "all"]
        for i, d in enumerate(dims):
            if d[0] == "all":
                if not piece:
                    raise _link_error(link, "Connection could not be resolved: more target "
                                            "placeholders than source dimensions")
                if i == holes[-1]:
                    n = math.prod(piece)
                    piece = []
                else:
                    n = piece.pop(0)
                lists.append(list(range(n)))
                extents.append(n)
            else:
                if _reaches_past(d, max_elements()):
                    raise _link_error(link, f"the target selector reaches past the largest "
                                            f"buffer allowed ({max_elements()} elements)")
                lists.append(selector_indices(d, 0))
                # a range reaches to its end, so [0:6:2] spans 6 elements
                extents.append(d[1] + 1 if d[0] == "index" else max(d[2], 1))
        if rank is None:
            rank = len(lists)
        elif rank != len(lists):
            raise _link_error(link, f"Cannot extend a rank-{rank} range with a "
                                    f"rank-{len(lists)} range")
        count = math.prod([len(i) for i in lists]) if lists else 0
        if count != math.prod(link.piece_shape) or (count == 0 and link.dst_sel is not None):
            raise _link_error(link, f"Connection could not be resolved: the target selects "
                                    f"{count} elements but the source gives "
                                    f"{math.prod(link.piece_shape)}")
        coords_per_link.append((lists, extents))
    shape = tuple(max(extents[d] for _, extents in coords_per_link) for d in range(rank))
    if fixed_shape is not None:
        if len(fixed_shape) != rank or any(s > f for s, f in zip(shape, fixed_shape)):
            raise _link_error(links[0], f'writes outside fixed size of input "{buffer.name}" '
                                        f"{tuple(fixed_shape)}")
        shape = tuple(fixed_shape)
    for link, (lists, _) in zip(links, coords_per_link):
        grids = np.meshgrid(*[np.array(i, dtype=np.intp) for i in lists], indexing="ij")
        link.dst_index = np.ravel_multi_index([g.ravel() for g in grids], shape)
    return shape


def runs_into(buffer: Buffer, memo: dict, stack: tuple = ()) -> list[Run]:
    """The runs from module outputs that fill an input or port, following ports upstream.

    Delays add along the hops; a window on one hop shifts by the single delays of the others;
    two windows on one path are an error.
    """
    if buffer in memo:
        return memo[buffer]
    if buffer in stack:
        raise ModelError(f"group ports form a loop at {buffer.path}")
    runs: list[Run] = []
    incoming = buffer.incoming
    for link in incoming if len(incoming) == 1 else sorted(incoming, key=lambda lk: lk.order):
        if len(link.delays) == 1:
            lanes = [(link.delays[0], link.dst_index)]
        else:
            n = len(link.src_index)
            lanes = [(d, link.dst_index[k * n:(k + 1) * n]) for k, d in enumerate(link.delays)]
        if link.source.kind == "output":
            for d, dst in lanes:
                runs.append(Run(link.source, buffer, d, link.src_index, dst, link.node,
                                link.window, [link]))
            continue
        upstream = runs_into(link.source, memo, stack + (buffer,))
        size = link.source.size
        owner = np.full(size, -1, dtype=np.intp)
        where = np.zeros(size, dtype=np.intp)
        for r, run in enumerate(upstream):
            owner[run.dst_index] = r
            where[run.dst_index] = run.src_index
        src_index = np.asarray(link.src_index)
        for d, dst in lanes:
            dst = np.asarray(dst)
            src_owner = owner[src_index]
            for r in np.unique(src_owner[src_owner >= 0]):
                up = upstream[r]
                if up.window and link.window:
                    raise _link_error(link, "two delay windows on one path through group "
                                            "ports are not allowed")
                mask = src_owner == r
                runs.append(Run(up.source, buffer, up.delay + d, where[src_index[mask]],
                                dst[mask], link.node, up.window or link.window,
                                up.links + [link]))
    if len(incoming) > 1:
        uncover(runs, buffer.size)
    memo[buffer] = runs
    return runs
