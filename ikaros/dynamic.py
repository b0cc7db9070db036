"""Dynamic arrays: the values of Ikaros 3 dynamic outputs (``dynamic="yes"`` with a
``capacity``), whose shape changes at run time within a fixed capacity."""
from __future__ import annotations

import math

import numpy as np
from numpy.lib.mixins import NDArrayOperatorsMixin


class DynamicArray(NDArrayOperatorsMixin):
    """An array whose shape changes at run time, never beyond its capacity.

    A module sees one as a dynamic output (which it writes) and as an input fed by a dynamic
    output (which it only reads); the object itself never changes, its shape does. It starts
    with 0 rows. ``shape`` is the current shape and ``capacity`` the largest, of the same
    rank; ``data`` is a float32 view of the current values (a new view after each change of
    shape). NumPy functions and operators take the object itself as its current values
    (``np.sum(self.INPUT)``, ``self.INPUT * 2``), and array attributes and methods not
    defined here are those of ``data`` (``self.INPUT.reshape(-1)``).

    Write it with ``set(values)``, ``append(row)`` or ``resize(shape)`` and then ``data``::

        self.OUTPUT.set([[1, 2], [3, 4]])      # shape (2, 2)
        self.OUTPUT.append([5, 6])             # shape (3, 2)
        self.OUTPUT.resize((1, 2))             # keeps the first element(s): [[1, 2]]
        self.OUTPUT.data[0, 1] = 7
    """

    __slots__ = ("storage", "_flat", "shape", "data")

    def __init__(self, capacity: tuple):
        self.storage = np.zeros(tuple(capacity), dtype=np.float32)   # the whole capacity
        self._flat = self.storage.reshape(-1)
        self.shape: tuple = ()
        self.data: np.ndarray = self._flat
        self.resize((0,) + tuple(capacity[1:]))

    @property
    def capacity(self) -> tuple:
        return self.storage.shape

    @property
    def size(self) -> int:
        return self.data.size

    @property
    def ndim(self) -> int:
        return len(self.shape)

    def resize(self, shape) -> None:
        """Make the current shape ``shape`` (same rank as the capacity, no dimension above
        it). The values keep their order in memory: the leading elements are kept, new ones
        hold what was last stored there."""
        shape = (int(shape),) if np.isscalar(shape) else tuple(int(s) for s in shape)
        capacity = self.storage.shape
        if len(shape) != len(capacity) or any(not 0 <= s <= c
                                               for s, c in zip(shape, capacity)):
            raise ValueError(f"shape {shape} does not fit the capacity {capacity} of the "
                             f"dynamic array")
        if shape != self.shape:
            self.shape = shape
            self.data = self._flat[:math.prod(shape)].reshape(shape)

    def set(self, values) -> None:
        """Take the shape and the values of ``values`` (a rank-1 capacity takes any
        sequence; a higher rank takes arrays of its rank)."""
        values = np.asarray(values, dtype=np.float32)
        if values.ndim != len(self.storage.shape) and values.size == 0:
            values = values.reshape((0,) + self.storage.shape[1:])
        self.resize(values.shape)
        self.data[...] = values

    def append(self, row) -> None:
        """Add one row at the end (a value for a rank-1 capacity)."""
        n = self.shape[0]
        self.resize((n + 1,) + self.shape[1:])
        self.data[n] = row

    def clear(self) -> None:
        """No rows."""
        self.resize((0,) + self.shape[1:])

    def assign(self, other: "DynamicArray") -> None:
        """Take the shape and values of another dynamic array of the same capacity (how the
        kernel copies one along a connection)."""
        if other.shape != self.shape:
            self.shape = other.shape
            self.data = self._flat[:other.data.size].reshape(other.shape)
        n = other.data.size
        self._flat[:n] = other._flat[:n]

    def __array_ufunc__(self, ufunc, method, *inputs, **kwargs):
        inputs = tuple(x.data if isinstance(x, DynamicArray) else x for x in inputs)
        if "out" in kwargs:
            kwargs["out"] = tuple(x.data if isinstance(x, DynamicArray) else x
                                  for x in kwargs["out"])
        return getattr(ufunc, method)(*inputs, **kwargs)

    def __getattr__(self, name):
        if name.startswith("__"):
            raise AttributeError(name)
        return getattr(self.data, name)

    def __array__(self, dtype=None, copy=None):
        if dtype is not None and dtype != self.data.dtype:
            return self.data.astype(dtype)
        return self.data.copy() if copy else self.data

    def __len__(self) -> int:
        return self.shape[0]

    def __getitem__(self, key):
        return self.data[key]

    def __setitem__(self, key, value):
        self.data[key] = value

    def __repr__(self):
        return f"DynamicArray(shape={self.shape}, capacity={self.capacity})"
