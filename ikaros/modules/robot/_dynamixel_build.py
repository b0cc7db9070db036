"""The Dynamixel module's build: which servos, and which element of the arrays each is."""
from __future__ import annotations

import numpy as np


def first_found(tables: dict, wanted: int, max_id: int, described: str) -> dict:
    """The ``wanted`` lowest ids of a scan (``number_of_servos``); fewer found is an error."""
    if len(tables) < wanted:
        raise ValueError(f"the scan of ids 0..{max_id} on {described} found {len(tables)} servos "
                         f"({', '.join(map(str, sorted(tables))) or 'none'}); number_of_servos is {wanted}")
    return {ident: tables[ident] for ident in sorted(tables)[:wanted]}


def elements(index_mode: str, size: int, ids: list[int], order: list[int]) -> tuple[int, np.ndarray]:
    """The array size and the element of each servo of ``ids`` (in id order) for ``index_mode``:
    its id (direct), or its place in ``order``, the listed or scanned ids (indirect); ``size``
    above 0 forces the array size."""
    if index_mode == "direct":
        element = {ident: ident for ident in ids}
        natural = max(order) + 1
    else:
        element = {ident: order.index(ident) for ident in ids}
        natural = len(order)
    size = size if size > 0 else natural
    outside = [ident for ident in ids if element[ident] >= size]
    if outside:
        raise ValueError(f'size="{size}" leaves no element for servo {", ".join(map(str, outside))} '
                         f'(index_mode="{index_mode}" needs at least {natural})')
    return size, np.array([element[ident] for ident in ids], dtype=int)


def describe(bus, tables: dict, full: bool) -> str:
    """The servos found on ``bus``, by model (``full``: one line each with its model number)."""
    models: dict[str, list[int]] = {}
    for ident, table in tables.items():
        models.setdefault(table.model, []).append(ident)
    text = f"{len(tables)} servos on {bus}: " + "; ".join(f"{m} {ids}" for m, ids in models.items())
    if full:
        for ident, table in tables.items():
            text += f"\n  id {ident}: {table.model} (model number {table.model_number}, {table.series})"
    return text
