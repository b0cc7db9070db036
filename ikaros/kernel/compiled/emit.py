"""Instructions for the standard operations: one emitter per ``compiled_op`` name.

A module class opts in with ``compiled_op = "NAME"`` (the class's own ``tick`` must compute
what the operation computes; a subclass that overrides ``tick`` runs in Python). An emitter
writes the module's instructions into a ``Fragment`` and returns a loader: a function of
the parameter array and the module's first slot in it that writes the module's current
parameter values into its slots (from ``Fragment.slots``) and says whether the
module can run compiled with them (False: it runs its Python tick until a later change says
True again).
"""
from __future__ import annotations

import numpy as np

from . import ops


class Fragment:
    """The instructions of one module, with parameter slots and index-pool entries numbered
    from 0 (the plan moves them to the module's place in the whole program)."""

    __slots__ = ("rows", "param_count", "pool", "pool_size")

    def __init__(self):
        self.rows: list[tuple] = []
        self.param_count = 0
        self.pool: list[np.ndarray] = []
        self.pool_size = 0

    def emit(self, op: int, out: int = 0, n: int = 0, a: int = 0, b: int = -1,
             param: int = 0) -> None:
        self.rows.append((op, out, n, a, b, param))

    def slots(self, count: int) -> int:
        """Reserve ``count`` parameter slots; returns the first."""
        first = self.param_count
        self.param_count += count
        return first

    def indices(self, flat: np.ndarray) -> int:
        """Put arena indices into the pool; returns where they start."""
        first = self.pool_size
        self.pool.append(np.asarray(flat, dtype=np.int64))
        self.pool_size += len(flat)
        return first


def _run_start(index) -> int | None:
    """The first element of an element map that is n, n+1, ..., else None."""
    if isinstance(index, range):
        return index.start if index.step == 1 and len(index) else None
    if len(index) == 0:
        return None
    start = int(index[0])
    return start if np.array_equal(index, np.arange(start, start + len(index))) else None


def emit_copy(frag: Fragment, run) -> None:
    """A zero-delay connection: elements ``src_index`` of the source to ``dst_index``."""
    n = len(run.src_index)
    if n == 0:
        return
    s, d = _run_start(run.src_index), _run_start(run.dst_index)
    if s is not None and d is not None:
        frag.emit(ops.COPY, run.target.offset + d, n, run.source.offset + s)
        return
    src = frag.indices(np.asarray(run.src_index, dtype=np.int64) + run.source.offset)
    dst = frag.indices(np.asarray(run.dst_index, dtype=np.int64) + run.target.offset)
    frag.emit(ops.GATHER, 0, n, src, dst)


def _port(ports: dict, name: str, size: int | None = None):
    """A connected port's buffer (of ``size`` elements when given), else None."""
    buf = ports.get(name)
    if buf is None or buf.array is None or buf.offset is None:
        return None
    if size is not None and buf.size != size:
        return None
    return buf


def _elementwise(inputs: dict, outputs: dict, *names: str):
    """OUTPUT and the inputs ``names``, each connected and of OUTPUT's size, else None."""
    out = _port(outputs, "OUTPUT")
    if out is None:
        return None
    found = [_port(inputs, name, out.size) for name in names]
    return None if any(port is None for port in found) else (out, *found)


def _binary(op):
    def emit(frag, module, inputs, outputs):
        ports = _elementwise(inputs, outputs, "INPUT1", "INPUT2")
        if ports is None:
            return None
        out, a, b = ports
        frag.emit(op, out.offset, out.size, a.offset, b.offset)
        return no_parameters
    return emit


def no_parameters(params, base) -> bool:
    """The loader of a module without parameters."""
    return True


def _unary(op, module_ok=None):
    def emit(frag, module, inputs, outputs):
        ports = _elementwise(inputs, outputs, "INPUT")
        if ports is None:
            return None
        out, x = ports
        frag.emit(op, out.offset, out.size, x.offset)
        if module_ok is None:
            return no_parameters
        return lambda params, base: module_ok(module)
    return emit


def _subtract(frag, module, inputs, outputs):
    ports = _elementwise(inputs, outputs, "INPUT1")
    if ports is None:
        return None
    out, a = ports
    if "INPUT2" not in module._ik_connected:
        frag.emit(ops.COPY, out.offset, out.size, a.offset)
        return no_parameters
    b = _port(inputs, "INPUT2", out.size)
    if b is None:
        return None
    frag.emit(ops.SUBTRACT, out.offset, out.size, a.offset, b.offset)
    return no_parameters


def _scale(frag, module, inputs, outputs):
    ports = _elementwise(inputs, outputs, "INPUT")
    if ports is None:
        return None
    out, x = ports
    scale = -1
    if "SCALE" in module._ik_connected:
        s = _port(inputs, "SCALE")
        if s is None or s.size == 0:
            return None
        scale = s.offset
    p = frag.slots(1)
    frag.emit(ops.SCALE, out.offset, out.size, x.offset, scale, p)

    def load(params, base):
        params[base + p] = module.factor
        return True
    return load


def _threshold(frag, module, inputs, outputs):
    ports = _elementwise(inputs, outputs, "INPUT")
    if ports is None:
        return None
    out, x = ports
    p = frag.slots(3)
    frag.emit(ops.THRESHOLD, out.offset, out.size, x.offset, -1, p)

    def load(params, base):
        params[base + p] = 1.0 if module.bypass else 0.0
        params[base + p + 1] = 1.0 if module.type == "linear" else 0.0
        params[base + p + 2] = module.threshold
        return True
    return load


def _sum(frag, module, inputs, outputs):
    out = _port(outputs, "OUTPUT", 1)
    x = out and _port(inputs, "INPUT")
    if x is None:
        return None
    frag.emit(ops.SUM, out.offset, x.size, x.offset)
    return no_parameters


def _constant(frag, module, inputs, outputs):
    out = _port(outputs, "OUTPUT")
    if out is None:
        return None
    p = frag.slots(out.size)
    frag.emit(ops.CONSTANT, out.offset, out.size, 0, -1, p)

    def load(params, base):
        data = np.asarray(module.data).reshape(-1)
        n = min(out.size, data.size)
        params[base + p:base + p + n] = data[:n]
        params[base + p + n:base + p + out.size] = 0
        return True
    return load


def _integrator(frag, module, inputs, outputs):
    ports = _elementwise(inputs, outputs, "INPUT")
    if ports is None:
        return None
    out, x = ports
    p = frag.slots(6)
    frag.emit(ops.INTEGRATE, out.offset, out.size, x.offset, -1, p)
    limit = type(module)._limit

    def load(params, base):
        try:
            low, high = limit(module.min, "min"), limit(module.max, "max")
        except ValueError:
            return False         # the Python tick reports the bad limit
        params[base + p], params[base + p + 1] = module.alpha, module.beta
        params[base + p + 2], params[base + p + 3] = (0.0, 0.0) if low is None else (1.0, low)
        params[base + p + 4], params[base + p + 5] = (0.0, 0.0) if high is None else (1.0, high)
        return True
    return load


EMITTERS = {
    "add": _binary(ops.ADD),
    "subtract": _subtract,
    "multiply": _binary(ops.MULTIPLY),
    "divide": _binary(ops.DIVIDE),
    "maximum": _binary(ops.MAXIMUM),
    "minimum": _binary(ops.MINIMUM),
    "scale": _scale,
    "abs": _unary(ops.ABS),
    "tanh": _unary(ops.TANH, module_ok=lambda m: not m.debug),
    "threshold": _threshold,
    "sum": _sum,
    "constant": _constant,
    "integrator": _integrator,
}
