"""The compiled tick's plan: which modules run as instructions, in what order, and the
calls that run them (one per stretch of compiled modules, between the Python ones)."""
from __future__ import annotations

import collections
import heapq

import numpy as np

from . import ops
from .emit import EMITTERS, Fragment, emit_copy


def emitter(module):
    """The emitter of a module's class, or None when the class has no compiled operation
    or its tick is not the one that declared it."""
    cls = type(module)
    for klass in cls.__mro__:
        if "compiled_op" in vars(klass):
            if cls.tick is not klass.tick:
                return None
            return EMITTERS.get(klass.compiled_op)
    return None


def fragment(inst, inputs: dict, outputs: dict, copies: list, block: np.ndarray):
    """The instructions of one module (its zero-delay copies, then its tick) and its
    loader, or None when it runs in Python."""
    if inst.asynchronous or inst.period != 1:
        return None
    emit = emitter(inst.module)
    if emit is None:
        return None
    for buf in list(inputs.values()) + list(outputs.values()):
        if buf.array is not None and buf.array.base is not block:
            return None
    frag = Fragment()
    for run in copies:
        if run.source.array.base is not block:
            return None
        emit_copy(frag, run)
    load = emit(frag, inst.module, inputs, outputs)
    return None if load is None else (frag, load)


def grouped_order(schedule: list, edges: dict, compiled: set) -> list:
    """A schedule order (zero-delay sources first) that keeps compiled modules together:
    the modules of one kind (compiled or not) are taken as long as any is ready, each kind
    in schedule order."""
    position = {inst: i for i, inst in enumerate(schedule)}
    successors = collections.defaultdict(list)
    waiting = dict.fromkeys(schedule, 0)
    for (a, b) in edges:
        successors[a].append(b)
        waiting[b] += 1
    ready = {True: [], False: []}
    for inst in schedule:
        if waiting[inst] == 0:
            ready[inst in compiled].append((position[inst], inst))
    kind = not ready[False]        # Python modules first (often sources: devices, files)
    order = []
    while ready[True] or ready[False]:
        if not ready[kind]:
            kind = not kind
        _, inst = heapq.heappop(ready[kind])
        order.append(inst)
        for nxt in successors[inst]:
            waiting[nxt] -= 1
            if waiting[nxt] == 0:
                heapq.heappush(ready[nxt in compiled], (position[nxt], nxt))
    return order


class Program:
    """All instructions of a network, with their parameter slots and index pool."""

    def __init__(self, block: np.ndarray, fragments: list):
        self.block = block
        rows, pool, self.slots, self.loaders = [], [], [], []
        self.owner_of_row: list = []
        n_params = n_pool = 0
        self.ranges = {}                     # inst -> (first row, last row + 1)
        for inst, frag, load in fragments:
            first = len(rows)
            for op, out, n, a, b, p in frag.rows:
                if op == ops.GATHER:
                    a, b = a + n_pool, b + n_pool
                rows.append((op, out, n, a, b, p + n_params))
                self.owner_of_row.append(inst)
            self.ranges[inst] = (first, len(rows))
            self.slots.append((inst, n_params, frag.param_count, load))
            n_params += frag.param_count
            pool.extend(frag.pool)
            n_pool += frag.pool_size
        self.code = np.array(rows, dtype=np.int64).reshape(-1, ops.WIDTH)
        self.params = np.zeros(max(n_params, 1), dtype=np.float32)
        self.pool = np.concatenate(pool) if pool else np.zeros(1, dtype=np.int64)
        self.flags = np.zeros(max(len(rows), 1), dtype=np.int64)
        self.loader = {inst: (first, count, load) for inst, first, count, load in self.slots}

    def load(self, inst) -> bool:
        """Write a module's parameters into its slots; whether it can run compiled."""
        first, count, load = self.loader[inst]
        return bool(load(self.params[first:first + count]))


class CompiledRun:
    """One call of the compiled function for a stretch of compiled modules, in order. A
    member whose parameters cannot run compiled (until they change again) runs its Python
    calls in its place."""

    def __init__(self, program: Program, members: list, python_calls: dict, execute):
        self.program = program
        self.members = members
        self.python_calls = python_calls
        self.execute = execute
        self.fallback: set = set()
        self.failed = None            # the member whose Python call raised, for the report
        for inst in members:
            if not program.load(inst):
                self.fallback.add(inst)
        self._pieces()

    def _pieces(self) -> None:
        """The calls of one tick: (first, last) row ranges, and Python members."""
        pieces, ranges = [], self.program.ranges
        for inst in self.members:
            if inst in self.fallback:
                pieces.append(inst)
                continue
            first, last = ranges[inst]
            if pieces and isinstance(pieces[-1], list) and pieces[-1][1] == first:
                pieces[-1][1] = last
            else:
                pieces.append([first, last])
        self.pieces = [tuple(p) if isinstance(p, list) else p for p in pieces]
        single = len(self.pieces) == 1 and isinstance(self.pieces[0], tuple)
        self.span = self.pieces[0] if single else None

    def refresh(self, inst) -> None:
        """A member's parameters changed: load them again."""
        ok = self.program.load(inst)
        if ok != (inst not in self.fallback):
            (self.fallback.discard if ok else self.fallback.add)(inst)
            self._pieces()

    def _run(self, first: int, last: int) -> None:
        p = self.program
        if self.execute(p.block, p.code, first, last, p.params, p.pool, p.flags):
            self._flagged(first, last)

    def _flagged(self, first: int, last: int) -> None:
        """Instructions that met a case their module reports (a division by zero): the
        module's Python tick computes the same output again and reports it."""
        flags = self.program.flags
        for k in np.flatnonzero(flags[first:last]):
            flags[first + k] = 0
            inst = self.program.owner_of_row[first + k]
            self.failed = inst
            inst.module.tick()
        self.failed = None

    def __call__(self) -> None:
        if self.span is not None:
            self._run(*self.span)
            return
        for piece in self.pieces:
            if isinstance(piece, tuple):
                self._run(*piece)
            else:
                self.failed = piece
                for call in self.python_calls[piece]:
                    call()
                self.failed = None


def compiled_plan(schedule: list, edges: dict, buffers: dict, runs: list, shared: dict,
                  block: np.ndarray, calls: dict, minimum: int, executor):
    """The tick's calls with compiled stretches: (sequence, owner, compiled run of each
    compiled module), or None when fewer than ``minimum`` modules can be compiled or
    ``executor()`` gives no compiled function."""
    copies = collections.defaultdict(list)
    for run in runs:
        if run.delay == 0 and run.target not in shared:
            copies[run.target.owner].append(run)
    fragments = {}
    for inst in schedule:
        inputs, outputs = buffers[inst]
        made = fragment(inst, inputs, outputs, copies[inst], block)
        if made is not None:
            fragments[inst] = made
    if not fragments or len(fragments) < minimum:
        return None
    execute = executor()
    if execute is None:
        return None
    order = grouped_order(schedule, edges, set(fragments))
    program = Program(block, [(inst, *fragments[inst]) for inst in order
                              if inst in fragments])
    execute(block, program.code, 0, 0, program.params, program.pool, program.flags)  # load
    sequence, owner, compiled = [], {}, {}
    stretch: list = []

    def close_stretch():
        if stretch:
            run = CompiledRun(program, list(stretch), calls, execute)
            sequence.append(run)
            owner[run] = stretch[0]
            for inst in stretch:
                compiled[inst] = run
            stretch.clear()

    for inst in order:
        if inst in fragments:
            stretch.append(inst)
            continue
        close_stretch()
        for call in calls[inst]:
            sequence.append(call)
            owner[call] = inst
    close_stretch()
    return sequence, owner, compiled
