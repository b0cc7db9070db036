"""The compiled tick's plan: which modules run as instructions, in what order, and the
calls that run them (one per stretch of compiled modules, between the Python ones)."""
from __future__ import annotations

import collections
import functools
import heapq

import numpy as np

from . import ops
from . import user
from .emit import EMITTERS, Fragment, emit_copy, no_parameters


@functools.lru_cache(maxsize=None)
def emitter(cls):
    """The emitter of a module class, or None when the class has no compiled operation or
    its tick is not the one of the class that declared it."""
    for klass in cls.__mro__:
        if "compiled_op" in vars(klass):
            if cls.tick is not klass.tick:
                return None
            return EMITTERS.get(klass.compiled_op)
    return None


ARRAY_LIMIT = 4096   # elements; a module with a larger array gains nothing, NumPy runs it


def _in_arena(inputs: dict, outputs: dict) -> bool:
    """Whether a module's arrays are all in the arena (every buffer with an offset is:
    network.py puts them there), none of them large. Dynamic buffers are not, so the
    modules that touch one run as Python."""
    for ports in (inputs, outputs):
        for buf in ports.values():
            if buf.array is not None and (buf.offset is None or
                                          buf.array.size > ARRAY_LIMIT):
                return False
    return True


def copies_fragment(copies: list) -> Fragment:
    """The instructions of a module's zero-delay copies (runs into its inputs)."""
    frag = Fragment()
    for run in copies:
        emit_copy(frag, run)
    return frag


def fragment(inst, inputs: dict, outputs: dict, copies: list):
    """How a module runs compiled: (kind, fragment, loader), where kind is "standard" for
    the instructions of a standard operation (its zero-delay copies, then its tick) and
    (class, argument layout) for a user module's compiled tick; or None (Python)."""
    if inst.asynchronous or not inst.every_tick or not _in_arena(inputs, outputs):
        return None
    module = inst.module
    emit = emitter(type(module))
    if emit is not None:
        frag = copies_fragment(copies)
        load = emit(frag, module, inputs, outputs)
        return None if load is None else ("standard", frag, load)
    function = user.compiled_tick(type(module))
    args = function and user.layout(module, function)
    if not args:
        return None
    frag, load = user.user_fragment(module, inputs, outputs, args)
    return (type(module), args), frag, load


def grouped_order(schedule: list, edges: dict, kinds: dict) -> list:
    """A schedule order (zero-delay sources first) that keeps modules of one kind together
    (Python modules have no kind): a kind is taken as long as any of its modules is ready,
    each kind in schedule order; then the ready Python modules, then the kind of the first
    ready module."""
    if len(kinds) == len(schedule) and len(set(kinds.values())) == 1:
        return list(schedule)                      # one kind: the schedule as it is
    position = {inst: i for i, inst in enumerate(schedule)}
    successors = collections.defaultdict(list)
    waiting = dict.fromkeys(schedule, 0)
    for (a, b) in edges:
        successors[a].append(b)
        waiting[b] += 1
    ready: dict = collections.defaultdict(list)
    for inst in schedule:
        if waiting[inst] == 0:
            ready[kinds.get(inst)].append((position[inst], inst))
    order, kind = [], None
    while len(order) < len(schedule):
        if not ready[kind]:
            kind = None if ready[None] else min(
                (heap[0][0], k) for k, heap in ready.items() if heap and k is not None)[1]
        _, inst = heapq.heappop(ready[kind])
        order.append(inst)
        for nxt in successors[inst]:
            waiting[nxt] -= 1
            if waiting[nxt] == 0:
                heapq.heappush(ready[kinds.get(nxt)], (position[nxt], nxt))
    return order


class Table:
    """The rows of many modules in one int64 array, with their parameter slots (moved to
    the module's place: ``param_column`` of every row, and the pool positions of gathers)."""

    def __init__(self, fragments: list, param_column: int, width: int):
        self.param_column = param_column
        self.owner_of_row: list = []
        self.ranges: dict = {}                     # inst -> (first row, last row + 1)
        self.loaders: dict = {}                    # inst -> (first slot, loader)
        rows, param_base, pool_base, pool = [], [], [], []
        n_params = n_pool = 0
        for inst, frag, load in fragments:
            first, count = len(rows), len(frag.rows)
            rows.extend(frag.rows)
            self.owner_of_row.extend([inst] * count)
            param_base.extend([n_params] * count)
            pool_base.extend([n_pool] * count)
            self.ranges[inst] = (first, first + count)
            self.loaders[inst] = (n_params, load)
            n_params += frag.param_count
            pool.extend(frag.pool)
            n_pool += frag.pool_size
        code = np.array(rows, dtype=np.int64).reshape(-1, width)
        code[:, param_column] += np.array(param_base, dtype=np.int64)
        if pool:
            gathers = code[:, 0] == ops.GATHER
            shift = np.array(pool_base, dtype=np.int64)[gathers]
            code[gathers, ops.A] += shift
            code[gathers, ops.B] += shift
        self.code = code
        self.params = np.zeros(max(n_params, 1), dtype=np.float32)
        self.pool = np.concatenate(pool) if pool else np.zeros(1, dtype=np.int64)
        self.flags = np.zeros(max(len(rows), 1), dtype=np.int64)

    def load(self, inst) -> bool:
        """Write a module's parameters into its slots; whether it can run compiled."""
        first, load = self.loaders[inst]
        return bool(load(self.params, first))


class CompiledRun:
    """One call of a compiled function for a stretch of modules of one kind, in order. A
    member whose parameters cannot run compiled (until they change again) runs its Python
    calls in its place. ``call(first, last)`` runs rows first..last-1 of ``table`` and
    returns how many of them flagged a case their module reports (a division by zero)."""

    def __init__(self, table: Table, members: list, python_calls: dict, call):
        self.table = table
        self.members = members
        self.python_calls = python_calls
        self.call = call
        self.fallback: set = set()
        self.failed = None            # the member whose Python call raised, for the report
        for inst in members:
            if not table.load(inst):
                self.fallback.add(inst)
        self._pieces()

    def _pieces(self) -> None:
        """The calls of one tick: (first, last) row ranges, and Python members."""
        pieces, ranges = [], self.table.ranges
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
        ok = self.table.load(inst)
        if ok != (inst not in self.fallback):
            (self.fallback.discard if ok else self.fallback.add)(inst)
            self._pieces()

    def _run(self, first: int, last: int) -> None:
        try:
            flagged = self.call(first, last)
        except Exception:
            user_runner = self.table.param_column != ops.PARAM   # it notes its row
            self.failed = self.table.owner_of_row[self.table.flags[0]] if user_runner else None
            raise
        if flagged:
            self._flagged(first, last)

    def _flagged(self, first: int, last: int) -> None:
        """The module's Python tick computes the same output again and reports the case."""
        flags = self.table.flags
        for k in np.flatnonzero(flags[first:last]):
            flags[first + k] = 0
            inst = self.table.owner_of_row[first + k]
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
                  block: np.ndarray, calls: dict, minimum: int, executor,
                  cancelled=None):
    """The tick's calls with compiled stretches: (sequence, owner, compiled run of each
    compiled module), or None when fewer than ``minimum`` modules can be compiled,
    ``executor()`` gives no compiled function, or ``cancelled`` (an Event: the network was
    closed meanwhile) is set."""
    copies = collections.defaultdict(list)
    for run in runs:
        if run.delay == 0 and run.target not in shared:
            copies[run.target.owner].append(run)
    made = {}
    for k, inst in enumerate(schedule):
        if cancelled is not None and not k % 256 and cancelled.is_set():
            return None
        inputs, outputs = buffers[inst]
        m = fragment(inst, inputs, outputs, copies[inst])
        if m is not None:
            made[inst] = m
    if not made or len(made) < minimum:
        return None
    execute = executor()
    if execute is None or cancelled is not None and cancelled.is_set():
        return None
    runners = {}
    for kind in dict.fromkeys(m[0] for m in made.values() if m[0] != "standard"):
        runners[kind] = _runner(kind, [inst for inst in made if made[inst][0] == kind])
        if runners[kind] is None:
            made = {inst: m for inst, m in made.items() if m[0] != kind}
    kinds = {inst: m[0] for inst, m in made.items()}
    order = grouped_order(schedule, edges, kinds)
    standard = [(inst, made[inst][1], made[inst][2]) for inst in order
                if kinds.get(inst) == "standard"]
    users = [inst for inst in order if inst in made and kinds[inst] != "standard"]
    # a user module's copies are standard instructions after all others, run by its row
    program = Table(standard + [(inst, copies_fragment(copies[inst]), no_parameters)
                                for inst in users], ops.PARAM, ops.WIDTH)
    code, params, pool, flags = program.code, program.params, program.pool, program.flags

    def standard_call(first, last):
        return execute(block, code, first, last, params, pool, flags)

    tables = {}
    for kind in dict.fromkeys(kinds[inst] for inst in users):
        members = [inst for inst in users if kinds[inst] == kind]
        frags = []
        for inst in members:
            frag, load = made[inst][1], made[inst][2]
            frag.rows = [program.ranges[inst] + row for row in frag.rows]
            frags.append((inst, frag, load))
        table = Table(frags, 2, len(frags[0][1].rows[0]))
        tables[kind] = table, _user_call(runners[kind], block, table, program)
    sequence, owner, compiled = [], {}, {}
    stretch: list = []

    def close_stretch():
        if stretch:
            kind = kinds[stretch[0]]
            table, call = (program, standard_call) if kind == "standard" else tables[kind]
            run = CompiledRun(table, list(stretch), calls, call)
            sequence.append(run)
            owner[run] = stretch[0]
            for inst in stretch:
                compiled[inst] = run
            stretch.clear()

    for inst in order:
        if inst in made:
            if stretch and kinds[stretch[0]] != kinds[inst]:
                close_stretch()
            stretch.append(inst)
            continue
        close_stretch()
        for call in calls[inst]:
            sequence.append(call)
            owner[call] = inst
    close_stretch()
    return sequence, owner, compiled


def _runner(kind, members: list):
    """A user class's runner, compiled (or loaded from the cache) now; None, with a
    warning from the first member, when numba cannot compile its tick."""
    cls, args = kind
    try:
        run = user.runner(cls, args, user.compiled_tick(cls))
        f32, i64 = np.zeros(1, np.float32), np.zeros(1, np.int64)
        run(f32, np.zeros((0, 3 + 2 * sum(k == "array" for k, _ in args)), np.int64), 0, 0,
            f32, np.zeros((0, ops.WIDTH), np.int64), f32, i64, i64, i64)
    except Exception as e:
        first = " ".join(str(e).split())[:300]
        members[0].module.warning(f"the compiled_tick of {cls.__name__} cannot be compiled, "
                                  f"so its Python tick runs: {type(e).__name__}: {first}")
        return None
    return run


def _user_call(run, block, table, program):
    rows, params, where = table.code, table.params, table.flags
    code, cparams, pool, flags = program.code, program.params, program.pool, program.flags

    def call(first, last):
        return run(block, rows, first, last, params, code, cparams, pool, flags, where)
    return call


def compiled_gather(block: np.ndarray, src: np.ndarray, dst: np.ndarray, execute,
                    tap=None, tick: int = -1):
    """A copy of arena elements ``src`` to ``dst`` (the delay-1 copies of small buffers) as
    one instruction of the compiled function; with ``tap`` (a kernel.taps.OutputTap, the
    arena holding the values of ``tick``), the tap's row comes first, in the same call, and
    the tap is called back when the call flags it."""
    n = len(src)
    code = [[ops.GATHER, 0, n, 0, n, 0]]
    pool = [src, dst]
    params = np.zeros(1, dtype=np.float32)
    if tap is not None:
        k = tap.index.size
        code.insert(0, [ops.TAP, 0, k, 2 * n, 2 * n + k, 0])
        pool += [tap.index, np.zeros(ops.TAP_STATE + len(tap.ticks), np.int64)]
        params = tap.rows.reshape(-1)
    code = np.array(code, dtype=np.int64)
    pool = np.concatenate(pool).astype(np.int64)
    flags = np.zeros(len(code), dtype=np.int64)
    last = len(code)
    if tap is None:
        def copy():
            execute(block, code, 0, last, params, pool, flags)
        return copy
    tap.bind(pool[2 * n + tap.index.size:], tick)
    signal = tap.on_signal

    def copy_and_tap():
        if execute(block, code, 0, last, params, pool, flags):
            signal()
    return copy_and_tap
