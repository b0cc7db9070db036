"""Which outputs a recording keeps, and where their values are in the kernel's arena."""
from __future__ import annotations

import fnmatch
from dataclasses import dataclass

import numpy as np

from ..language.writer import to_text


@dataclass(frozen=True)
class Signal:
    """One recorded output: its address, shape and its columns in a recorded row."""
    name: str
    shape: tuple
    start: int
    stop: int


def select_outputs(net, only: list[str] | str | None = None) -> tuple[list[Signal], np.ndarray]:
    """The outputs whose addresses match any glob pattern in ``only`` (every output when
    None), in schedule order, and the arena indices of their elements in row order.
    Dynamic outputs (whose shape changes while the model runs) are not recorded.

    Raises ValueError when a pattern matches no output."""
    patterns = [only] if isinstance(only, str) else list(only or [])
    outputs = [buf for inst in net.schedule for buf in net._buffers[inst][1].values()
               if buf.size > 0 and not buf.dynamic]
    if patterns:
        unmatched = [p for p in patterns
                     if not any(fnmatch.fnmatchcase(b.path, p) for b in outputs)]
        if unmatched:
            raise ValueError(f'no output matches {", ".join(repr(p) for p in unmatched)} '
                             f'(outputs are addressed like "Group.Module.OUTPUT")')
        outputs = [b for b in outputs if any(fnmatch.fnmatchcase(b.path, p) for p in patterns)]
    signals, index, column = [], [], 0
    for buf in outputs:
        signals.append(Signal(buf.path, tuple(buf.shape), column, column + buf.size))
        index.append(np.arange(buf.offset, buf.offset + buf.size, dtype=np.intp))
        column += buf.size
    return signals, np.concatenate(index) if index else np.zeros(0, np.intp)


def module_parameters(net) -> dict[str, str]:
    """Every module parameter's current value as model-file text, by address."""
    from ..language.values import value_text
    values = {}
    for inst in net.schedule:
        for name in inst.values:
            path = f"{inst.path}.{name}"
            value = net.parameter(path)
            values[path] = value if isinstance(value, str) else \
                "" if value is None else value_text(value)
    return values


def seeds(parameters: dict[str, str]) -> dict[str, str]:
    """The parameters named seed (of random generators), by address."""
    return {path: value for path, value in parameters.items()
            if path.rsplit(".", 1)[-1] == "seed"}


def model_text(net) -> str:
    """The text of the model a recording keeps: its file as it is, or the tree written
    out (a model built in code)."""
    try:
        with open(net.filename, encoding="utf-8") as f:
            return f.read()
    except (OSError, TypeError, UnicodeDecodeError):
        return to_text(net.model)
