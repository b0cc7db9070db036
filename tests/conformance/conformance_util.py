"""Helpers for the conformance suite: models live in ./models beside their test-only classes."""
import os

import numpy as np

import ikaros

MODELS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "models")


def model(name: str) -> str:
    return os.path.join(MODELS, name)


def load(name: str, **overrides):
    return ikaros.load(model(name), **overrides)


def line_of(name: str, marker: str) -> int:
    """The 1-based line of the first line in a model file that contains ``marker``."""
    lines = lines_of(name, marker)
    assert lines, f"{marker!r} not in {name}"
    return lines[0]


def lines_of(name: str, marker: str) -> list[int]:
    with open(model(name), encoding="utf-8") as f:
        return [i for i, text in enumerate(f, start=1) if marker in text]


def trace(net, paths, ticks: int):
    """Step ``ticks`` times; after each tick record a copy of every path."""
    out = []
    for _ in range(ticks):
        net.step()
        out.append({p: net.output(p) for p in paths})
    return out


def same(actual, expected):
    """Exact comparison of shape and values (float32 data, exact small integers)."""
    expected = np.asarray(expected, dtype=np.float32)
    actual = np.asarray(actual)
    assert actual.shape == expected.shape, f"shape {actual.shape} != {expected.shape}"
    assert np.array_equal(actual, expected), f"{actual.tolist()} != {expected.tolist()}"


def x(k: int) -> float:
    """The Seq source: 100 written in init (tick -1), 101 + k in tick k, 0 before that."""
    return 101.0 + k if k >= -1 else 0.0


def v(k: int) -> list:
    """The SeqVec source: [100, 200] in init, [101 + k, 201 + k] in tick k."""
    return [101.0 + k, 201.0 + k] if k >= -1 else [0.0, 0.0]


