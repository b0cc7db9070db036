"""The check after a tick that no module replaced the array of one of its ports.

A module's ports are attributes holding the arrays the kernel connected; ``self.OUTPUT =
[1, 2]`` binds the attribute to a new object, so the value never reaches the output (and
``self.INPUT = ...`` hides the input). The check compares identities in C (``map`` of
``operator.is_`` over the modules' attribute dictionaries and the arrays), only for the
modules whose Python tick runs (not those the compiled or fused tick computes): every port
after the first tick, then a slice of ``SLICE`` ports after each tick in turn, so that it
costs a few microseconds per tick however large the model (a port replaced later is found
within ports / SLICE ticks). Only when an identity differs is the culprit looked for.
"""
from __future__ import annotations

import operator

from ..module import attribute_name

SLICE = 16          # ports checked after each tick (all of them after the first)


class ReplacedPort(Exception):
    """A module's tick assigned to one of its ports instead of writing into it."""


def _message(attr: str, is_output: bool, when: str = "the tick") -> str:
    if is_output:
        return (f"{when} replaced its output {attr} (self.{attr} = ...), so the value "
                f"never reaches the output: write into the array instead, "
                f"self.{attr}[:] = ...")
    return (f"{when} assigned to its input {attr} (self.{attr} = ...): a module never "
            f"replaces or writes its inputs; read them (or work on a copy, "
            f"x = self.{attr}.copy())")


def bound_ports(module, ports: dict) -> list:
    """The objects bound to a module's port attributes now, in the order of ``ports``
    ({attribute: is_output}, as port_attributes gives)."""
    return list(map(vars(module).get, ports))


def replaced_in_init(module, ports: dict, before: list) -> ReplacedPort | None:
    """A ReplacedPort when ``init`` bound a port attribute to another object than the
    kernel's array it held before (``before``: bound_ports then)."""
    attributes = vars(module)
    if all(map(operator.is_, map(attributes.get, ports), before)):
        return None
    for (attr, is_output), array in zip(ports.items(), before):
        if array is not None and attributes.get(attr) is not array:
            return ReplacedPort(_message(attr, is_output, "init"))
    return None


def port_attributes(schedule: list, buffers: dict) -> list:
    """(instance, {attribute: is_output}) of each module in ``schedule`` (``buffers``:
    {instance: (inputs, outputs)} by port name). Modules with the same port names share
    one dict (it is only read)."""
    shared: dict = {}
    result = []
    for inst in schedule:
        inputs, outputs = buffers[inst]
        names = (tuple(inputs), tuple(outputs))
        ports = shared.get(names)
        if ports is None:
            ports = shared[names] = {**{attribute_name(n): False for n in inputs},
                                     **{attribute_name(n): True for n in outputs}}
        result.append((inst, ports))
    return result


class PortGuard:
    """Watches the port attributes of ``modules`` ((instance, {attribute: is_output})
    each) as they are bound now."""

    def __init__(self, modules: list):
        watched = [((inst, ports), attributes, attr, array)
                   for inst, ports in modules
                   for attributes in (vars(inst.module),)
                   for attr, array in zip(ports, map(attributes.get, ports))
                   if array is not None]        # (an unbound port is not watched)
        owners, dicts, names, arrays = (list(column) for column in zip(*watched)) \
            if watched else ([], [], [], [])
        self._owners = owners       # (instance, {attribute: is_output}) of each entry
        self._all = (dicts, names, arrays)
        self._slices = [(dicts[k:k + SLICE], names[k:k + SLICE], arrays[k:k + SLICE])
                        for k in range(0, len(dicts), SLICE)]
        self._next = -1             # the slice to check next; -1: all of them

    def __len__(self) -> int:
        return len(self._owners)

    def check(self) -> tuple | None:
        """None when the ports checked now hold their arrays, else (instance,
        ReplacedPort) for the first that does not."""
        k = self._next
        dicts, names, arrays = self._all if k < 0 else self._slices[k]
        self._next = (k + 1) % len(self._slices)
        if all(map(operator.is_, map(dict.get, dicts, names), arrays)):
            return None
        for (inst, ports), attributes, attr, array in zip(self._owners, *self._all):
            if attributes.get(attr) is not array:
                return inst, ReplacedPort(_message(attr, ports[attr]))
        return None
