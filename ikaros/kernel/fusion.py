"""Fusion: many instances of an element-wise class, at the same depth of the zero-delay
graph, computed as one NumPy operation over the buffer arena.

A class opts in with ``elementwise = (ufunc, operand, operand, ...)`` (the ufunc applied
left to right), or a list of such forms, the first whose inputs are exactly the connected
ones being used. An operand is an input name, ``"NAME[0]"`` (that input's first element, for
all elements) or ``"@parameter"`` (a number parameter, for all of the module's elements). The
result is the same as the module's tick when the tick applies the same ufuncs in the same
order on float32 values.
"""
from __future__ import annotations

import collections
import functools

import numpy as np


FUSE_LIMIT = 4096   # elements; larger arrays gain nothing from a gather and a scatter


def _in_block(block: np.ndarray, array) -> bool:
    # arena buffers are views of the block (NumPy keeps the owner as every view's base)
    return array is not None and array.base is block and array.flags.c_contiguous


def _input_name(operand: str) -> str:
    return operand[:-3] if operand.endswith("[0]") else operand


@functools.lru_cache(maxsize=None)
def _operands(form: tuple) -> tuple[frozenset, tuple]:
    """The inputs a form reads, and its input operands as (operand, input name, whether
    only the first element is read)."""
    operands = tuple((o, _input_name(o), o.endswith("[0]")) for o in form[1:]
                     if not o.startswith("@"))
    return frozenset(name for _, name, _ in operands), operands


def fused_form(inst, inputs: dict, outputs: dict, block: np.ndarray) -> tuple | None:
    """The element-wise form an instance can be fused with, or None."""
    forms = getattr(type(inst.module), "elementwise", None)
    if forms is None or inst.asynchronous or not inst.every_tick or len(outputs) != 1:
        return None
    out = next(iter(outputs.values())).array
    if not _in_block(block, out) or out.size > FUSE_LIMIT:
        return None
    connected = inst.module._ik_connected
    for form in (forms if isinstance(forms, list) else [forms]):
        names, operands = _operands(form)
        if names != connected:
            continue
        for _, name, first in operands:
            arr = inputs[name].array
            if not _in_block(block, arr) or (arr.size != out.size and not first):
                return None
        return form
    return None


def _levels(schedule: list, edges: dict) -> dict:
    """Each module's depth in the zero-delay graph: 0 without zero-delay inputs, else one
    more than its deepest source."""
    preds: dict = {}
    for (a, b) in edges:
        found = preds.get(b)
        if found is None:
            preds[b] = [a]
        else:
            found.append(a)
    level = {}
    for inst in schedule:
        found = preds.get(inst)
        level[inst] = 1 + max(map(level.__getitem__, found)) if found else 0
    return level


class FusedOp:
    """One ufunc over the elements of several modules: gather, compute, scatter."""

    def __init__(self, block: np.ndarray, spec: tuple, members: list):
        self.block = block
        self.ufunc = getattr(np, spec[0])
        self.members = members                     # (inst, inputs, outputs)
        self.operands = spec[1:]
        sizes = np.array([next(iter(out.values())).array.size for _, _, out in members])
        self.starts = np.concatenate([[0], np.cumsum(sizes)])
        total = int(self.starts[-1])
        within = np.arange(total) - np.repeat(self.starts[:-1], sizes)   # 0.. in each member

        def spread(offsets, whole=True):
            """Flat arena indices of each member's elements, from its start offset."""
            return np.repeat(np.array(offsets, dtype=np.intp), sizes) + (within if whole else 0)

        out_idx = spread([next(iter(out.values())).offset for _, _, out in members])
        first = int(out_idx[0])
        if np.array_equal(out_idx, np.arange(first, first + total)):
            self.out_view, self.out_idx = block[first:first + total], None
        else:
            self.out_view, self.out_idx = np.zeros(total, np.float32), out_idx
        self.gathers = []
        self.args = []
        self.params: dict[str, np.ndarray] = {}
        for operand in self.operands:
            if operand.startswith("@"):
                vec = np.zeros(total, np.float32)
                self.params[operand[1:]] = vec
                self.args.append(vec)
            else:
                name, first = _input_name(operand), operand.endswith("[0]")
                idx = spread([ins[name].offset for _, ins, _ in members], whole=not first)
                scratch = np.zeros(total, np.float32)
                self.gathers.append((idx.astype(np.intp), scratch))
                self.args.append(scratch)
        for k in range(len(members)):
            self._load(k)

    def _load(self, k: int) -> None:
        module = self.members[k][0].module
        a, b = self.starts[k], self.starts[k + 1]
        for name, vec in self.params.items():
            vec[a:b] = getattr(module, name)

    def refresh(self, inst) -> None:
        """Read a member's parameters again after they changed."""
        for k, (member, _, _) in enumerate(self.members):
            if member is inst:
                self._load(k)

    def __call__(self) -> None:
        block = self.block
        for idx, scratch in self.gathers:
            np.take(block, idx, out=scratch)
        args, out, ufunc = self.args, self.out_view, self.ufunc
        ufunc(args[0], args[1], out=out)
        for arg in args[2:]:
            ufunc(out, arg, out=out)
        if self.out_idx is not None:
            block[self.out_idx] = self.out_view


def fuse(schedule: list, edges: dict, buffers: dict, block: np.ndarray, calls: dict,
         pre_tick: dict):
    """A tick's calls with fusable modules merged level by level.

    Returns (sequence, owner, fused) where ``fused`` maps each fused module to its
    operation, or None when nothing can be fused.
    """
    level = _levels(schedule, edges)
    width = collections.Counter(level.values())     # only modules of one level fuse
    forms = {}
    for inst in schedule:
        if width[level[inst]] > 1:
            inputs, outputs = buffers[inst]
            form = fused_form(inst, inputs, outputs, block)
            if form is not None:
                forms[inst] = form
    if len(forms) < 2:
        return None
    groups: dict = collections.defaultdict(list)
    for inst, form in forms.items():
        groups[(level[inst], form)].append((inst, *buffers[inst]))
    groups = {k: v for k, v in groups.items() if len(v) > 1}
    if not groups:
        return None
    fused, sequence, owner = {}, [], {}
    ops_by_level = collections.defaultdict(list)
    for (lvl, spec), members in groups.items():
        op = FusedOp(block, spec, members)
        ops_by_level[lvl].append(op)
        for inst, _, _ in members:
            fused[inst] = op
    unfused_by_level = collections.defaultdict(list)
    for inst in schedule:
        if inst not in fused:
            unfused_by_level[level[inst]].append(inst)
    for lvl in range(max(level.values()) + 1):
        for inst in unfused_by_level[lvl]:
            for call in calls[inst]:
                sequence.append(call)
                owner[call] = inst
        for op in ops_by_level[lvl]:
            for inst, _, _ in op.members:
                for copy in pre_tick.get(inst, ()):
                    sequence.append(copy)
                    owner[copy] = inst
            sequence.append(op)
            owner[op] = op.members[0][0]
    return sequence, owner, fused

