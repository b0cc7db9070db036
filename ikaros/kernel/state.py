"""Save, load and reset the state of a running network.

The state of a module is its outputs and the attributes its class names in ``state``::

    class Counter(Module):
        state = ("count", "history")     # attributes kept by save_state / load_state
        OUTPUT = Output(shape=1)

The state of the network is that of every module, plus its delay lines (the older values of
outputs read through delays of 2 or more) and the tick. A state file is JSON::

    {"format": "ikaros-state-v1", "tick": 120, "time": 1.2, "saved_at_utc": "...",
     "ikaros_version": "0.1.0", "model_filename": "demo.ikg", "model_name": "Demo",
     "scope": "network" | "<module or group path>", "item_count": 3,
     "items": {"A.OUTPUT": {"kind": "output", "type": "matrix", "shape": [2],
                            "value": [1, 2]},
               "A.count": {"kind": "state", "type": "int", "value": 4},
               "A.OUTPUT@delay": {"kind": "delay", "type": "matrix", "shape": [2, 2],
                                  "value": [[...], [...]]}}}

``reset_state`` restores the state every module had right after ``init`` (captured when the
network was built). Loading checks every item before it changes anything: a missing or
unknown item, a type or a shape that differs is an error naming the item, and the network
is left as it was.
"""
from __future__ import annotations

import datetime
import json
import os

import numpy as np

FORMAT = "ikaros-state-v1"
SCALARS = {bool: "bool", int: "int", float: "float", str: "string"}


class StateError(ValueError):
    """A state that can not be saved or loaded; the message names the item."""


def declared(module) -> tuple[str, ...]:
    """The attribute names a module's class declares as its state (checked when the class
    is defined, in ikaros/module.py)."""
    return tuple(getattr(type(module), "state", ()))


def _modules(net, scope: str | None):
    if not scope:
        return list(net.schedule)
    found = [m for m in net.schedule if m.path == scope or m.path.startswith(scope + ".")]
    if not found:
        raise StateError(f'no module or group "{scope}" with modules in {net.top.name}')
    return found


def _ages(ring) -> list[int]:
    """Row indices of a delay line, newest first."""
    return [(ring.pos - k) % ring.depth for k in range(ring.depth)]


def values(net, scope: str | None = None, keep=np.ndarray.copy) -> dict:
    """{item path: (kind, value)}: copies of the state of the modules in ``scope`` (a
    module or group path; all modules when empty). ``keep(array)`` makes what is kept of
    an output (a copy unless told otherwise)."""
    out = {}
    for inst in _modules(net, scope):
        _, outputs = net._buffers[inst]
        for name, buf in outputs.items():
            path = f"{inst.path}.{name}"
            out[path] = ("output", keep(buf.array))
            ring = net.rings.get(buf)
            if ring is not None:
                out[path + "@delay"] = ("delay", np.stack([ring.rows[k]
                                                           for k in _ages(ring)]))
        for attr in declared(inst.module):
            if not hasattr(inst.module, attr):
                raise StateError(f'{inst.path}: the state "{attr}" is not an attribute of '
                                 f'the module')
            value = getattr(inst.module, attr)
            if isinstance(value, np.ndarray):
                value = value.copy()
            elif isinstance(value, np.generic):
                value = value.item()
            out[f"{inst.path}.{attr}"] = ("state", value)
    return out


def _type(value) -> str:
    if isinstance(value, np.ndarray):
        return "matrix"
    for python, name in SCALARS.items():
        if type(value) is python:
            return name
    raise StateError(f"a value of type {type(value).__name__} can not be kept as state "
                     f"(arrays, bool, int, float and str can)")


def _item(kind: str, value) -> dict:
    t = _type(value)
    if t == "matrix":
        return {"kind": kind, "type": t, "shape": list(value.shape), "value": value.tolist()}
    if t == "float" and not np.isfinite(value):
        return {"kind": kind, "type": t, "value": str(value)}
    return {"kind": kind, "type": t, "value": value}


def collect(net, scope: str | None = None) -> dict:
    """{item path: item as in the file} of the modules in ``scope``."""
    return {path: _item(kind, v) for path, (kind, v) in values(net, scope).items()}


def _decode(path: str, item, current) -> object:
    if not isinstance(item, dict) or "value" not in item or "type" not in item:
        raise StateError(f'item "{path}" must be an object with "type" and "value"')
    want = _type(current)
    if item["type"] != want:
        raise StateError(f'item "{path}" has type "{item["type"]}" but the network\'s has '
                         f'type "{want}"')
    value = item["value"]
    if want == "matrix":
        try:
            arr = np.array(value, dtype=np.float64)
        except (TypeError, ValueError):
            raise StateError(f'item "{path}": the value is not a matrix of numbers') from None
        if arr.shape != current.shape:
            raise StateError(f'item "{path}" has shape {list(arr.shape)} but the network\'s '
                             f'has shape {list(current.shape)}')
        return arr
    if want == "float":
        if isinstance(value, str) and value in ("nan", "inf", "-inf"):
            return float(value)
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise StateError(f'item "{path}": expected a number')
        return float(value)
    python = {v: k for k, v in SCALARS.items()}[want]
    if type(value) is not python:
        raise StateError(f'item "{path}": expected a {want} value')
    return value


def _fit(now: dict, given: dict) -> None:
    missing = sorted(set(now) - set(given))
    unknown = sorted(set(given) - set(now))
    parts = []
    for what, names in (("missing", missing), ("not in the network", unknown)):
        if names:
            parts.append(f"{what}: " + ", ".join(names[:5]) + (" …" if len(names) > 5 else ""))
    if parts:
        raise StateError("the state does not fit the network (" + "; ".join(parts) + ")")


def _write(net, scope: str | None, new: dict) -> None:
    for inst in _modules(net, scope):
        _, outputs = net._buffers[inst]
        for name, buf in outputs.items():
            path = f"{inst.path}.{name}"
            np.copyto(buf.array, new[path], casting="unsafe")
            ring = net.rings.get(buf)
            if ring is not None:
                for row, k in zip(new[path + "@delay"], _ages(ring)):
                    np.copyto(ring.rows[k], row, casting="unsafe")
        for attr in declared(inst.module):
            value = new[f"{inst.path}.{attr}"]
            old = getattr(inst.module, attr)
            if isinstance(old, np.ndarray) and isinstance(value, np.ndarray) \
                    and old.shape == value.shape:
                np.copyto(old, value, casting="unsafe")
            else:
                setattr(inst.module, attr, value.copy() if isinstance(value, np.ndarray)
                        else value)


def apply(net, items: dict, scope: str | None = None) -> None:
    """Set the state of the modules in ``scope`` from file ``items``; every item is
    checked before anything changes."""
    now = values(net, scope)
    _fit(now, items)
    _write(net, scope, {p: _decode(p, items[p], v) for p, (_, v) in now.items()})


def save(net, filename: str, scope: str | None = None) -> dict:
    """Write the state of ``scope`` (all modules when empty) to ``filename``, whole or not
    at all; returns the file's header (everything but the items)."""
    items = collect(net, scope)
    data = {"format": FORMAT, "tick": net.tick, "time": net.clock.time,
            "saved_at_utc": datetime.datetime.now(datetime.timezone.utc).isoformat(
                timespec="seconds"),
            "ikaros_version": _version(),
            "model_filename": os.path.basename(net.filename or ""),
            "model_name": net.top.name, "scope": scope or "network",
            "item_count": len(items), "items": items}
    text = json.dumps(data, allow_nan=False)
    temporary = filename + ".tmp"
    with open(temporary, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(temporary, filename)
    return {k: v for k, v in data.items() if k != "items"}


def load(net, filename: str, scope: str | None = None) -> dict:
    """Read a state file written by ``save`` into the modules of ``scope``; with the whole
    network, the tick and time are restored too. Returns the file's header."""
    try:
        with open(filename, encoding="utf-8") as f:
            data = json.load(f)
    except OSError as e:
        raise StateError(f"cannot read {os.path.basename(filename)}: {e.strerror or e}") \
            from None
    except ValueError as e:
        raise StateError(f"{os.path.basename(filename)} is not JSON: {e}") from None
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        raise StateError(f"{os.path.basename(filename)}: unsupported format (expected "
                         f'"{FORMAT}")')
    if not isinstance(data.get("items"), dict):
        raise StateError(f"{os.path.basename(filename)} does not contain an items object")
    saved_scope = data.get("scope") or "network"
    if (scope or "network") != saved_scope:
        raise StateError(f'the file holds the state of "{saved_scope}", not of '
                         f'"{scope or "network"}"')
    apply(net, data["items"], scope)
    if not scope and isinstance(data.get("tick"), int) and data["tick"] >= 0:
        net.tick = data["tick"]
        net.clock.tick = data["tick"]
        net.clock.time = data["tick"] * net.clock.tick_duration
    return {k: v for k, v in data.items() if k != "items"}


class _Zeros:
    """An array that was all zeros after init: kept as its shape only (most outputs are,
    and a big model's buffers need not be held twice)."""

    def __init__(self, shape, dtype):
        self.shape, self.dtype = shape, dtype

    def array(self) -> np.ndarray:
        return np.zeros(self.shape, self.dtype)


def capture_initial(net) -> dict:
    """The state right after init, kept for ``reset``."""
    zeros: dict[tuple, _Zeros] = {}     # one for all arrays alike

    def kept(array: np.ndarray):
        if np.count_nonzero(array):         # (a tenth of the time of array.any())
            return array.copy()
        key = (array.shape, array.dtype)
        zero = zeros.get(key)
        if zero is None:
            zero = zeros[key] = _Zeros(*key)
        return zero

    out = {}
    for path, (kind, value) in values(net, keep=kept).items():
        if kind != "output" and isinstance(value, np.ndarray) and not np.count_nonzero(value):
            value = kept(value)       # a delay line or a state array, copied already
        out[path] = value
    return out


def reset(net, scope: str | None = None) -> None:
    """Every module in ``scope`` back to its state right after init; with the whole
    network, the tick goes back to 0."""
    now = values(net, scope)
    initial = {path: net.initial_state[path] for path in now}
    _write(net, scope, {path: v.array() if isinstance(v, _Zeros) else v
                        for path, v in initial.items()})
    if not scope:
        net.tick = 0
        net.clock.tick = 0
        net.clock.time = 0.0


def _version() -> str:
    from .. import __version__
    return __version__
