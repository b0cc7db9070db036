"""What a module keeps across a rebuild follows the new network's buffers.

When the editor's Apply (``Network.apply``) keeps a module that did not change, what its code
set on itself goes on into the new network (carry.py). Some of it refers to the replaced
network: its ports themselves (``self._a = self.INPUT1``), views of them (``self.INPUT1
.reshape(...)``), lists, dicts and helper objects that hold them, closures and bound methods.
Left alone, the module would read inputs nothing writes any more and write outputs nobody
reads: frozen. ``Follower`` replaces every such reference by the same view of the new
network's array (and the old module, its clock and dynamic arrays by the new ones).

What cannot be followed (a view that spans memory of the old network beyond one of the
module's own arrays) raises ``Unfollowable``: the module then starts afresh. Memory held by
objects Python cannot look into (a C extension's own pointers) is out of reach.
"""
from __future__ import annotations

import functools
import types

import numpy as np

try:                                      # NumPy >= 2
    from numpy.lib.array_utils import byte_bounds as _bounds
except ImportError:                       # NumPy 1.x
    _bounds = np.byte_bounds

_ATOMS = (type(None), bool, int, float, complex, str, bytes, np.generic, type,
          types.ModuleType)


class Unfollowable(Exception):
    """A reference to the replaced network that has no counterpart in the new one."""


class Follower:
    """Maps objects of a replaced network to the new network's.

    ``arrays``: (old, new) pairs of one module's arrays (ports, array parameters): a view
    of an old one becomes the same view of the new one. ``objects``: (old, new) pairs of
    objects replaced as they are (by identity: they need not be hashable). ``memory``: the old network's other arrays (its whole arena), into
    which no reference may point."""

    def __init__(self, arrays: list, objects: list, memory: list):
        self._objects = {id(old): new for old, new in objects}
        self._keep = [old for old, _ in objects]   # (the ids stay valid)
        self._arrays = [(_bounds(old), old, new) for old, new in arrays
                        if old.shape == new.shape and old.dtype == new.dtype
                        and old.strides == new.strides]
        self._memory = [_bounds(a) for a in memory if a is not None and a.size]
        self._done: dict[int, object] = {}       # id -> what it became
        self._seen: list = []                    # (keeps those ids valid)

    def follow(self, value):
        """``value`` with every reference to the old network replaced (containers and
        objects are changed in place; tuples, views and bound methods are made anew)."""
        if isinstance(value, _ATOMS):
            return value
        key = id(value)
        if key in self._objects:
            return self._objects[key]
        if key in self._done:
            return self._done[key]
        self._seen.append(value)
        self._done[key] = value                  # (a cycle meets the object itself)
        result = self._follow(value)
        self._done[key] = result
        return result

    def _follow(self, value):
        if isinstance(value, np.ndarray):
            return self._array(value)
        if isinstance(value, list):
            for k, item in enumerate(value):
                self._set(value, k, item)
            return value
        if isinstance(value, dict):
            for k, item in list(value.items()):
                self._set(value, k, item)
            return value
        if isinstance(value, tuple):
            items = [self.follow(x) for x in value]
            if all(a is b for a, b in zip(items, value)):
                return value
            return type(value)(*items) if hasattr(value, "_fields") else type(value)(items)
        if isinstance(value, types.MethodType):
            owner = self.follow(value.__self__)
            return value if owner is value.__self__ else types.MethodType(value.__func__, owner)
        if isinstance(value, types.BuiltinMethodType):     # self.OUTPUT.fill and the like
            owner = getattr(value, "__self__", None)
            if owner is None or isinstance(owner, types.ModuleType):
                return value
            new = self.follow(owner)
            return value if new is owner else getattr(new, value.__name__)
        if isinstance(value, types.FunctionType):
            for cell in value.__closure__ or ():
                try:
                    old = cell.cell_contents
                except ValueError:               # an empty cell
                    continue
                new = self.follow(old)
                if new is not old:
                    cell.cell_contents = new
            return value
        if isinstance(value, functools.partial):
            parts = (self.follow(value.func), self.follow(value.args),
                     self.follow(dict(value.keywords)))
            return functools.partial(parts[0], *parts[1], **parts[2])
        self._attributes(value)
        return value

    def _attributes(self, obj) -> None:
        """The attributes of an object (in its ``__dict__`` and ``__slots__``), in place."""
        own = getattr(obj, "__dict__", None)
        if isinstance(own, dict):
            for name, item in list(own.items()):
                self._set(own, name, item)
        for klass in type(obj).__mro__:
            slots = vars(klass).get("__slots__", ())
            for name in (slots,) if isinstance(slots, str) else slots:
                if name in ("__dict__", "__weakref__"):
                    continue
                try:
                    old = object.__getattribute__(obj, name)
                except AttributeError:
                    continue
                new = self.follow(old)
                if new is not old:
                    object.__setattr__(obj, name, new)

    def _set(self, container, key, item) -> None:
        """``container[key]`` followed, written only when it changes."""
        new = self.follow(item)
        if new is not item:
            container[key] = new

    def _array(self, value: np.ndarray):
        if value.dtype == object:
            for index, item in np.ndenumerate(value):
                self._set(value, index, item)
            return value
        if not value.size:
            return value
        low, high = _bounds(value)
        for (start, end), old, new in self._arrays:
            if value is old:
                return new
            if start <= low and high <= end:
                return _same_view(value, old, new)
        if any(low < end and start < high for start, end in self._memory):
            raise Unfollowable(f"an array (shape {value.shape}) that views the replaced "
                               f"network's memory beyond the module's own arrays")
        return value


class _Interface:
    """An object that hands NumPy an array interface (what ``as_strided`` does)."""

    def __init__(self, interface: dict, base: np.ndarray):
        self.__array_interface__ = interface
        self.base = base


def _same_view(value: np.ndarray, old: np.ndarray, new: np.ndarray) -> np.ndarray:
    """The view of ``new`` that ``value`` is of ``old`` (same start, shape, strides, type)."""
    start = value.__array_interface__["data"][0] - old.__array_interface__["data"][0]
    interface = {"shape": value.shape, "strides": value.strides,
                 "typestr": value.dtype.str, "version": 3,
                 "data": (new.__array_interface__["data"][0] + start,
                          not value.flags.writeable)}
    if value.dtype.fields is not None:
        interface["descr"] = value.dtype.descr
    view = np.asarray(_Interface(interface, new))
    return view if type(value) is np.ndarray else view.view(type(value))
