"""Changing a running model: a network built again from an edited model tree takes over from
the running one, keeping the state of every module that did not change. The editor's Apply
and ``Network.apply`` both use it.

A module did not change when it has the same path, the same class, the same parameter values
and the same input and output shapes in both networks (a new connection to it does not make
it new). Its state is carried over: the values of its outputs, the history of its delayed
outputs, and every attribute its code set on itself (``self.count``, a random generator ...).
The run goes on from the tick it had reached. Every other module starts afresh, as after a
load."""
from __future__ import annotations

import os

import numpy as np

from ..module import attribute_name, parameter_attribute
from .codeclasses import CodeClassRegistry
from .tree import ModuleInstance

_KERNEL_ATTRIBUTES = {"name", "path", "element", "clock", "description"}


def _same_values(a: dict, b: dict) -> bool:
    if a.keys() != b.keys():
        return False
    for key, value in a.items():
        other = b[key]
        if isinstance(value, np.ndarray) or isinstance(other, np.ndarray):
            if not (np.shape(value) == np.shape(other) and
                    np.array_equal(value, other, equal_nan=True)):
                return False
        elif value != other and not (value != value and other != other):   # nan == nan
            return False
    return True


def _shapes(net, inst: ModuleInstance) -> tuple:
    inputs, outputs = net._buffers[inst]
    return ({n: (b.shape if b.incoming else None) for n, b in inputs.items()},
            {n: b.shape for n, b in outputs.items()})


def unchanged(old_net, old: ModuleInstance, new_net, new: ModuleInstance) -> bool:
    """Whether ``new`` is the same module as ``old``, so that it may take over its state."""
    old_cls, new_cls = type(old.module), type(new.module)
    return (old.entry.name == new.entry.name
            and (old_cls.__module__, old_cls.__qualname__) ==
                (new_cls.__module__, new_cls.__qualname__)
            and old.asynchronous == new.asynchronous is False
            and _same_values(old.values, new.values)
            and _shapes(old_net, old) == _shapes(new_net, new))


def _private_state(inst: ModuleInstance) -> dict:
    """The attributes a module's code set on itself (not ports, parameters or the kernel's)."""
    module = inst.module
    skip = set(_KERNEL_ATTRIBUTES)
    skip.update(attribute_name(n) for n in module._ik_inputs)
    skip.update(attribute_name(n) for n in module._ik_outputs)
    skip.update(parameter_attribute(n) for n in inst.values)
    return {k: v for k, v in vars(module).items()
            if not k.startswith("_ik_") and k not in skip}


def carry_state(old, new) -> list[str]:
    """Give ``new`` the state of every module of ``old`` that did not change, and ``old``'s
    tick; returns the paths of the modules that kept their state. ``old`` must not be
    ticking."""
    kept = []
    for path, inst in new.modules.items():
        before = old.modules.get(path)
        if before is None or not unchanged(old, before, new, inst):
            continue
        old_outputs, new_outputs = old._buffers[before][1], new._buffers[inst][1]
        for name, buf in new_outputs.items():
            source = old_outputs[name]
            if buf.dynamic_array is not None and source.dynamic_array is not None:
                buf.dynamic_array.assign(source.dynamic_array)
            elif buf.array is not None and source.array is not None:
                np.copyto(buf.array, source.array)
                _carry_history(old.rings.get(source), new.rings.get(buf))
        for key, value in _private_state(before).items():
            setattr(inst.module, key, value)
        kept.append(path)
    new.tick = old.tick
    new.clock.tick = old.clock.tick
    new.clock.time = old.clock.time
    return kept


def _carry_history(old_ring, new_ring) -> None:
    """The values an output had in the ticks before, for the connections that delay it."""
    if old_ring is None or new_ring is None:
        return
    for delay in range(2, min(old_ring.depth, new_ring.depth) + 2):
        np.copyto(new_ring.row(delay), old_ring.row(delay))


def take_over(old, new) -> list[str]:
    """Make ``new`` go on where ``old`` (stopped, not yet closed) was: the modules' state
    (``carry_state``), the log level, profiling and the hooks called after each tick.
    Returns the paths of the modules that kept their state."""
    kept = carry_state(old, new)
    new.log_level = old.log_level
    new.profiling = old.profiling
    hooks = list(old.controller.tick_hooks)
    old.controller.tick_hooks.clear()
    new.controller.tick_hooks.extend(hooks)
    return kept


def rebuild(old, tree, classes: dict | None = None):
    """Build ``tree`` (the model tree of ``old``, edited) with the settings ``old`` was
    loaded with, and make it take over from ``old``, which is closed. When the tree does not
    build, ModelError is raised and ``old`` runs on unchanged. The new network is made by
    the builder class that made ``old``."""
    registry = None
    if classes:
        registry = CodeClassRegistry([os.path.dirname(old.filename)], classes)
    new = old.builder_class(old.filename, old._overrides, model=tree, registry=registry,
                            diagnostics=old.diagnostics.fresh(), limits=old.limits,
                            user_data=getattr(old, "user_data", None)).build()
    old.controller.stop()
    old.controller.join(30)
    take_over(old, new)
    old.close()
    return new
