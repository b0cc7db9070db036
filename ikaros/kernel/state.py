"""Save, load and reset the state of a running network.

The state of a module is its outputs, its ``State`` items (Ikaros 3 ``<state>``: a matrix
is kept like an output, of kind "state"; a scalar has its declared type float, double, int,
bool or string) and the attributes its class names in ``state``::

    class Counter(Module):
        state = ("count", "history")     # attributes kept by save_state / load_state
        bias = State(0.0, "a scalar state item", type="float")
        OUTPUT = Output(shape=1)

The state of the network is that of every module, plus its delay lines (the older values of
outputs read through delays of 2 or more) and the tick. A dynamic output is kept with its
current shape; its delay line is not kept, and is emptied (no rows) when the state is loaded
or reset. A state file is JSON::

    {"format": "ikaros-state-v1", "tick": 120, "time": 1.2, "saved_at_utc": "...",
     "ikaros_version": "0.1.0", "model_filename": "demo.ikg", "model_name": "Demo",
     "scope": "network" | "<module or group path>", "item_count": 3,
     "items": {"A.OUTPUT": {"kind": "output", "type": "matrix", "shape": [2],
                            "value": [1, 2]},
               "A.count": {"kind": "state", "type": "int", "value": 4},
               "A.ROWS": {"kind": "dynamic", "type": "matrix", "shape": [1, 2],
                          "value": [[5, 6]]},
               "A.OUTPUT@delay": {"kind": "delay", "type": "matrix", "shape": [2, 2],
                                  "value": [[...], [...]]}}}

``reset_state`` restores the state every module had right after ``init`` (captured when the
network was built). Loading checks every item before it changes anything: a missing or
unknown item, a type or a shape that differs is an error naming the item, and the network
is left as it was.
"""
from __future__ import annotations

import contextlib
import datetime
import json
import os

import numpy as np

from ..version import __version__

FORMAT = "ikaros-state-v1"
SCALARS = {bool: "bool", int: "int", float: "float", str: "string"}


class StateError(ValueError):
    """A state that can not be saved or loaded; the message names the item."""


def declared(module) -> tuple[str, ...]:
    """The attribute names a module's class declares as its state: the names in ``state``
    (checked when the class is defined, in ikaros/module.py) and its scalar ``State``
    items (Ikaros 3 ``<state>``)."""
    return _declarations(module)[0]


def _scalar_types(module) -> dict[str, str]:
    """{name: declared type} of the scalar state items of a module's class."""
    return _declarations(module)[1]


def _declarations(module) -> tuple[tuple[str, ...], dict[str, str]]:
    """(declared, _scalar_types) of a module's class, made once per class description (a
    model of 10,000 modules then makes them once)."""
    cls = type(module)
    made = cls.__dict__.get("_ik_state_declarations")
    if made is None or made[0] is not cls.description:
        types = {st.name: st.type for st in cls.description.states if st.type != "matrix"}
        made = (cls.description, tuple(getattr(cls, "state", ())) + tuple(types), types)
        cls._ik_state_declarations = made
    return made[1], made[2]


def _modules(net, scope: str | None):
    if not scope:
        return list(net.schedule)
    found = [m for m in net.schedule if m.path == scope or m.path.startswith(scope + ".")]
    if not found:
        raise StateError(f'no module or group "{scope}" with modules in {net.top.name}')
    return found


def _between_jobs(net, scope: str | None) -> list:
    """The asynchronous jobs of the modules in ``scope``, each waited for and published:
    their state is read or written only between two jobs (as in Ikaros 3)."""
    jobs = [job for inst in _modules(net, scope)
            if (job := net.async_modules.get(inst)) is not None]
    for job in jobs:
        job.wait()
    return jobs


def _ages(ring) -> list[int]:
    """Row indices of a delay line, newest first."""
    return [(ring.pos - k) % ring.depth for k in range(ring.depth)]


def values(net, scope: str | None = None, keep=np.ndarray.copy,
           skip: set | frozenset = frozenset()) -> dict:
    """{item path: (kind, type, value)}: copies of the state of the modules in ``scope`` (a
    module or group path; all modules when empty) but those in ``skip``. ``type`` is
    "matrix", or a scalar's type: the one its ``State`` declares, or that of its value.
    ``keep(array)`` makes what is kept of an output (a copy unless told otherwise)."""
    out = {}
    for inst in _modules(net, scope):
        if inst in skip:
            continue
        _, outputs = net._buffers[inst]
        specs = inst.module._ik_outputs
        for name, buf in outputs.items():
            path = f"{inst.path}.{name}"
            if buf.dynamic_array is not None:     # its current shape and values
                out[path] = ("dynamic", "matrix", buf.dynamic_array.data.copy())
                continue
            kind = "state" if specs[name].private else "output"
            out[path] = (kind, "matrix", keep(buf.array))
            ring = net.rings.get(buf)
            if ring is not None:
                out[path + "@delay"] = ("delay", "matrix",
                                        np.stack([ring.rows[k] for k in _ages(ring)]))
        names, types = _declarations(inst.module)
        for attr in names:
            if not hasattr(inst.module, attr):
                raise StateError(f'{inst.path}: the state "{attr}" is not an attribute of '
                                 f'the module')
            value = getattr(inst.module, attr)
            if isinstance(value, np.ndarray):
                value = value.copy()
            elif isinstance(value, np.generic):
                value = value.item()
            out[f"{inst.path}.{attr}"] = ("state", types.get(attr) or _type(value), value)
    return out


def _type(value) -> str:
    if isinstance(value, np.ndarray):
        return "matrix"
    for python, name in SCALARS.items():
        if type(value) is python:
            return name
    raise StateError(f"a value of type {type(value).__name__} can not be kept as state "
                     f"(arrays, bool, int, float and str can)")


def _item(kind: str, stype: str, value) -> dict:
    if stype == "matrix":
        return {"kind": kind, "type": stype, "shape": list(value.shape),
                "value": value.tolist()}
    if stype in ("float", "double"):
        value = float(value)
        if not np.isfinite(value):
            return {"kind": kind, "type": stype, "value": str(value)}
    return {"kind": kind, "type": stype, "value": value}


def collect(net, scope: str | None = None) -> dict:
    """{item path: item as in the file} of the modules in ``scope``."""
    return {path: _item(kind, t, v) for path, (kind, t, v) in values(net, scope).items()}


REAL = ("float", "double")


def _decode(path: str, item, want: str, current, strict: bool,
            capacity: tuple | None = None) -> object:
    """A file item's value, checked against the network's item of type ``want``. A
    declared scalar (``strict``) takes only its own type; a plain Python float takes
    "float" and "double" alike. ``capacity``: of a dynamic output, whose shape may be any
    that fits it."""
    if not isinstance(item, dict) or "value" not in item or "type" not in item:
        raise StateError(f'item "{path}" must be an object with "type" and "value"')
    if item["type"] != want and not (not strict and want in REAL and item["type"] in REAL):
        raise StateError(f'item "{path}" has type "{item["type"]}" but target state has '
                         f'type "{want}"')
    value = item["value"]
    if want == "matrix":
        try:
            arr = np.array(value, dtype=np.float64)
        except (TypeError, ValueError):
            raise StateError(f'item "{path}": the value is not a matrix of numbers') from None
        if capacity is not None:
            if arr.ndim != len(capacity) or any(s > c for s, c in zip(arr.shape, capacity)):
                raise StateError(f'item "{path}" has shape {list(arr.shape)}, which does not '
                                 f'fit the capacity {list(capacity)} of the dynamic output')
        elif arr.shape != current.shape:
            raise StateError(f'item "{path}" has shape {list(arr.shape)} but the target has '
                             f'shape {list(current.shape)}')
        return arr
    if want in REAL:
        if isinstance(value, str) and value in ("nan", "inf", "-inf"):
            return float(value)
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise StateError(f'item "{path}": Expected number value, not {_shown(value)}')
        return float(value)
    python = {v: k for k, v in SCALARS.items()}[want]
    if type(value) is not python:
        what = {"bool": "Boolean", "int": "integer"}.get(want, want)
        raise StateError(f'item "{path}": Expected {what} value, not {_shown(value)}')
    return value


def _shown(value) -> str:
    text = json.dumps(value)
    return text if len(text) <= 40 else text[:37] + "..."


def _fit(now: dict, given: dict, partial: bool) -> None:
    missing = [] if partial else sorted(set(now) - set(given))
    unknown = sorted(set(given) - set(now))
    parts = []
    for what, names in (("missing", missing), ("not in the network", unknown)):
        if names:
            parts.append(f"{what}: " + ", ".join(names[:5]) + (" …" if len(names) > 5 else ""))
    if parts:
        raise StateError("the state does not fit the network (" + "; ".join(parts) + ")")


def _write(net, scope: str | None, new: dict) -> None:
    """Set the items in ``new`` (all of them, or the ones a partial file holds)."""
    for inst in _modules(net, scope):
        _, outputs = net._buffers[inst]
        for name, buf in outputs.items():
            path = f"{inst.path}.{name}"
            if path not in new:
                continue
            if buf.dynamic_array is not None:
                buf.dynamic_array.set(new[path])
                ring = net.dynamic_rings.get(buf)
                for row in ring.rows if ring is not None else ():
                    row.clear()             # its delay line is not kept: no older rows
                continue
            np.copyto(buf.array, new[path], casting="unsafe")
            ring = net.rings.get(buf)
            if ring is not None and path + "@delay" in new:
                for row, k in zip(new[path + "@delay"], _ages(ring)):
                    np.copyto(ring.rows[k], row, casting="unsafe")
        for attr in declared(inst.module):
            path = f"{inst.path}.{attr}"
            if path not in new:
                continue
            value = new[path]
            old = getattr(inst.module, attr)
            if isinstance(old, np.ndarray) and isinstance(value, np.ndarray) \
                    and old.shape == value.shape:
                np.copyto(old, value, casting="unsafe")
            else:
                setattr(inst.module, attr, value.copy() if isinstance(value, np.ndarray)
                        else value)


def apply(net, items: dict, scope: str | None = None, partial: bool = False) -> None:
    """Set the state of the modules in ``scope`` from file ``items``; every item is
    checked before anything changes. With ``partial`` (a file of Ikaros 3, which keeps
    only persistent outputs) items the file lacks are left as they are."""
    jobs = _between_jobs(net, scope)
    now = values(net, scope)
    _fit(now, items, partial)
    typed = {f"{inst.path}.{name}" for inst in _modules(net, scope)
             for name in _scalar_types(inst.module)}
    capacity = {f"{inst.path}.{name}": buf.dynamic_array.capacity
                for inst in _modules(net, scope)
                for name, buf in net._buffers[inst][1].items() if buf.dynamic_array is not None}
    _write(net, scope, {p: _decode(p, items[p], t, v, p in typed, capacity.get(p))
                        for p, (_, t, v) in now.items() if p in items})
    for job in jobs:
        job.adopt_outputs()


def save(net, filename: str, scope: str | None = None) -> dict:
    """Write the state of ``scope`` (all modules when empty) to ``filename``, whole or not
    at all; returns the file's header (everything but the items)."""
    _between_jobs(net, scope)
    items = collect(net, scope)
    data = {"format": FORMAT, "tick": net.tick, "time": net.tick * net.clock.tick_duration,
            "saved_at_utc": datetime.datetime.now(datetime.timezone.utc).isoformat(
                timespec="seconds"),
            "ikaros_version": __version__,
            "model_filename": os.path.basename(net.filename or ""),
            "model_name": net.top.name, "scope": scope or "network",
            "item_count": len(items), "items": items}
    text = json.dumps(data, allow_nan=False)
    temporary = filename + ".tmp"
    try:
        with open(temporary, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(temporary, filename)
    except OSError as e:        # a full disk: no half-written file is left, the error names it
        with contextlib.suppress(OSError):
            os.remove(temporary)
        raise OSError(e.errno, e.strerror or str(e), filename) from None
    return {k: v for k, v in data.items() if k != "items"}


def load(net, filename: str, scope: str | None = None) -> dict:
    """Read a state file written by ``save`` into the modules of ``scope``; with the whole
    network, the tick and time are restored too. Returns the file's header.

    A file saved from one module or group loads into another of the same make (its items
    are moved). A file written by Ikaros 3 (``ikaros_version`` 3.x) holds only persistent
    outputs and state, named from the top group: its items are applied and the rest is
    left as it is."""
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
    items = data["items"]
    original = str(data.get("ikaros_version", "")).startswith("3")
    if original:
        items = _without_top_name(items, data.get("model_name"), net.top.name)
    saved_scope = data.get("scope") or "network"
    target = scope or "network"
    if target != saved_scope:
        if "network" in (target, saved_scope):
            raise StateError(f'the file holds the state of "{saved_scope}", not of '
                             f'"{target}"')
        items = _remapped(items, saved_scope, target)
    apply(net, items, scope, partial=original)
    if not scope and isinstance(data.get("tick"), int) and data["tick"] >= 0:
        net.tick = data["tick"]
        net.clock.tick = data["tick"]
        net.clock.time = data["tick"] * net.clock.tick_duration
    return {k: v for k, v in data.items() if k != "items"}


def _without_top_name(items: dict, *names) -> dict:
    """Ikaros 3 names items by their full path, the top group's name first."""
    for name in filter(None, names):
        prefix = f"{name}."
        if items and all(k.startswith(prefix) for k in items):
            return {k[len(prefix):]: v for k, v in items.items()}
    return items


def _remapped(items: dict, saved: str, target: str) -> dict:
    """The items of a scoped file moved from the module or group it was saved from onto
    another (Ikaros 3 does this too)."""
    def moved(path):
        if path.startswith(saved + "."):
            return target + path[len(saved):]
        raise StateError(f'item "{path}" is not in the saved scope "{saved}"')
    return {moved(k): v for k, v in items.items()}


class _Zeros:
    """An array that was all zeros after init: kept as its shape only (most outputs are,
    and a big model's buffers need not be held twice)."""

    def __init__(self, shape, dtype):
        self.shape, self.dtype = shape, dtype

    def array(self) -> np.ndarray:
        return np.zeros(self.shape, self.dtype)


def capture_initial(net, scope: str | None = None,
                    skip: set | frozenset = frozenset()) -> dict:
    """The state right after init of the modules in ``scope`` but those in ``skip``, kept
    for ``reset``."""
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
    for path, (_, _, value) in values(net, scope, keep=kept, skip=skip).items():
        if isinstance(value, np.ndarray) and not np.count_nonzero(value):
            value = kept(value)       # a delay line, dynamic output or array attribute
        out[path] = value
    return out


def reset(net, scope: str | None = None) -> None:
    """Every module in ``scope`` back to its state right after init; with the whole
    network, the tick goes back to 0."""
    jobs = _between_jobs(net, scope)
    now = values(net, scope)
    initial = {path: net.initial_state[path] for path in now}
    _write(net, scope, {path: v.array() if isinstance(v, _Zeros) else v
                        for path, v in initial.items()})
    for job in jobs:
        job.adopt_outputs()
    if not scope:
        net.tick = 0
        net.clock.tick = 0
        net.clock.time = 0.0

