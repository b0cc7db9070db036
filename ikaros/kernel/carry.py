"""Changing a running model: a network built again from an edited model tree takes over from
the running one, keeping every module that did not change. The editor's Apply and
``Network.apply`` both use it.

A module did not change when it has the same path, the same class (and script), the same
parameter values and the same input and output shapes in both networks (a new connection to
it does not make it new). Such a module is not started again: the build knows the running
network (``Builder(predecessor=...)``) and leaves the module's ``init`` out, and the take-over
hands it everything it had: the values of its outputs, the history of its delayed outputs,
and every attribute its code set on itself (``self.count``, a random generator, an open
file, a device connection, a scripted module's worker). Whatever of that refers to the
replaced network's arrays follows the new ones (follow.py), so the module goes on computing
from its new inputs into its new outputs. The replaced network does not call its ``stop``.
The run goes on from the tick it had reached. Every other module starts afresh, as after a
load; so does a kept module when the running network has ended or when it holds a view of
memory that cannot follow (with a warning)."""
from __future__ import annotations

import os

import numpy as np

from ..module import WARNING, attribute_name, parameter_attribute
from .codeclasses import CodeClassRegistry
from .follow import Follower, Unfollowable
from .tree import ModuleInstance

# set on every module by the build: the new network's, never handed over
_KERNEL_ATTRIBUTES = {"name", "path", "element", "clock", "description", "user_data",
                      "dialect"}


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


def _shapes(buffers: dict, inst: ModuleInstance) -> tuple:
    inputs, outputs = buffers[inst]
    return ({n: (b.shape if b.incoming else None) for n, b in inputs.items()},
            {n: b.shape for n, b in outputs.items()})


def _code(cls) -> tuple:
    return cls.__module__, cls.__qualname__, getattr(cls, "script_digest", None)


def unchanged(old_buffers: dict, old: ModuleInstance, new_buffers: dict,
              new: ModuleInstance) -> bool:
    """Whether ``new`` is the same module as ``old`` (each with the buffers of its build:
    ``{instance: (inputs, outputs)}``), so that it may take over from it."""
    return (old.entry.name == new.entry.name
            and _code(type(old.module)) == _code(type(new.module))
            and old.asynchronous == new.asynchronous is False
            and _same_values(old.values, new.values)
            and _shapes(old_buffers, old) == _shapes(new_buffers, new))


def adoptable(old, builder) -> dict:
    """{new instance: old instance}: the modules of ``builder``'s build (sized and
    scheduled) that did not change from the running network ``old``. Their ``init`` is
    left out; ``take_over`` hands them their state."""
    if old.stopped:
        return {}
    found = {}
    for inst in builder.instances:
        before = old.modules.get(inst.path)
        if before is not None and unchanged(old._buffers, before, builder.buffers, inst):
            found[inst] = before
    return found


def _old_memory(old) -> list:
    """The arrays of ``old`` no reference of a module handed over may point into: its arena,
    its delay rings and the storage of its dynamic buffers."""
    memory = [old.arena.block, old.ring_arena.block]
    memory += [buf.array for ports in old._buffers.values() for side in ports
               for buf in side.values() if buf.dynamic_array is not None]
    return memory


def _follower(old, before: ModuleInstance, new, inst: ModuleInstance,
              memory: list) -> Follower:
    """What maps ``before``'s references into ``old`` (its arrays ``memory``) to ``inst``'s
    in ``new``."""
    arrays = []
    objects = [(before.module, inst.module), (before.module.clock, inst.module.clock)]
    old_ports, new_ports = old._buffers[before], new._buffers[inst]
    for old_side, new_side in zip(old_ports, new_ports):
        for name, buf in new_side.items():
            source = old_side[name]
            if source.array is not None and buf.array is not None:
                arrays.append((source.array, buf.array))
            if source.dynamic_array is not None and buf.dynamic_array is not None:
                objects.append((source.dynamic_array, buf.dynamic_array))
    for name in inst.values:
        a = getattr(before.module, parameter_attribute(name), None)
        b = getattr(inst.module, parameter_attribute(name), None)
        if isinstance(a, np.ndarray) and isinstance(b, np.ndarray):
            arrays.append((a, b))
    return Follower(arrays, objects, memory)


def _own_state(before: ModuleInstance, inst: ModuleInstance) -> dict:
    """What ``before``'s code set on itself (not its ports, parameters or what the build
    set on every module, which ``inst`` has of its own)."""
    module, fresh = before.module, vars(inst.module)
    skip = set(_KERNEL_ATTRIBUTES)
    skip.update(attribute_name(n) for n in module._ik_inputs)
    skip.update(attribute_name(n) for n in module._ik_outputs)
    skip.update(parameter_attribute(n) for n in inst.values)
    return {k: v for k, v in vars(module).items()
            if k not in skip and not (k.startswith("_ik_") and k in fresh)}


def _hand_over(old, before: ModuleInstance, new, inst: ModuleInstance, memory: list) -> None:
    """Give ``inst`` what ``before`` had; Unfollowable leaves ``inst`` as it was."""
    follower = _follower(old, before, new, inst, memory)
    state = {k: follower.follow(v) for k, v in _own_state(before, inst).items()}
    old_outputs, new_outputs = old._buffers[before][1], new._buffers[inst][1]
    for name, buf in new_outputs.items():
        source = old_outputs[name]
        if buf.dynamic_array is not None and source.dynamic_array is not None:
            buf.dynamic_array.assign(source.dynamic_array)
            _carry_dynamic_history(old.dynamic_rings.get(source), new.dynamic_rings.get(buf))
        elif buf.array is not None and source.array is not None:
            np.copyto(buf.array, source.array)
            _carry_history(old.rings.get(source), new.rings.get(buf))
    for key, value in state.items():
        setattr(inst.module, key, value)


def carry_state(old, new) -> list[str]:
    """Hand every module ``new`` left to be taken over (``adoptable``) what it had in
    ``old``, and give ``new`` ``old``'s tick; returns the paths of the modules that kept
    their state. ``old`` must not be ticking; it no longer stops the modules handed over.
    Those that cannot be handed over start now, as after a load."""
    kept = []
    new.tick = old.tick
    new.clock.tick = old.clock.tick
    new.clock.time = old.clock.time
    adopted = new.take_adopted()
    memory = _old_memory(old) if adopted else []
    initial: dict = {}                  # the old network's initial state, by module
    for key, value in old.initial_state.items():
        initial.setdefault(key.rpartition(".")[0], []).append((key, value))
    for inst, before in adopted.items():
        try:
            if old.stopped:
                raise Unfollowable("the running network had ended")
            _hand_over(old, before, new, inst, memory)
        except Unfollowable as e:
            new.notify(WARNING, inst.path, f"starts afresh after the change: {e}")
            new.start_late(inst)
            continue
        old.hand_over(before)
        kept.append(inst.path)
        new.initial_state.update(initial.get(before.path, ()))
    return kept


def _carry_history(old_ring, new_ring) -> None:
    """The values an output had in the ticks before, for the connections that delay it."""
    if old_ring is None or new_ring is None:
        return
    for delay in range(2, min(old_ring.depth, new_ring.depth) + 2):
        np.copyto(new_ring.row(delay), old_ring.row(delay))


def _carry_dynamic_history(old_ring, new_ring) -> None:
    if old_ring is None or new_ring is None:
        return
    for delay in range(2, min(old_ring.depth, new_ring.depth) + 2):
        new_ring.row(delay).assign(old_ring.row(delay))


def take_over(old, new) -> list[str]:
    """Make ``new`` (built with ``predecessor=old``) go on where ``old`` (stopped, not yet
    closed) was: the modules' state (``carry_state``), the log level, profiling and the
    hooks called after each tick. Returns the paths of the modules that kept their
    state."""
    kept = carry_state(old, new)
    new.log_level = old.log_level
    new.profiling = old.profiling
    if old._controller is not None:      # (a network stepped from Python has none)
        hooks = list(old.controller.tick_hooks)
        old.controller.tick_hooks.clear()
        new.controller.tick_hooks.extend(hooks)
    return kept


def rebuild(old, tree, classes: dict | None = None):
    """Build ``tree`` (the model tree of ``old``, edited) with the settings ``old`` was
    loaded with, and make it take over from ``old``, which is closed. When the tree does not
    build, ModelError is raised and ``old`` runs on unchanged. The new network is made by
    the builder class that made ``old``. A tree without a ``dialect`` attribute is read in
    ``old``'s dialect: an edit (a module added in the editor) does not change how the rest
    of the model is read."""
    overrides = dict(old._overrides)
    if "dialect" not in tree.attrs:
        overrides.setdefault("dialect", old.dialect)
    registry = None
    if classes:
        registry = CodeClassRegistry([os.path.dirname(old.filename)], classes)
    new = old.builder_class(old.filename, overrides, model=tree, registry=registry,
                            diagnostics=old.diagnostics.fresh(), limits=old.limits,
                            user_data=getattr(old, "user_data", None),
                            predecessor=old).build()
    new._overrides = old._overrides      # (the dialect kept above is not a setting of the run)
    if old._controller is not None:
        old.controller.stop()
        old.controller.join(30)
    take_over(old, new)
    old.close()
    return new
