"""What runs in one tick: module steps in schedule order, optionally in parallel thread groups,
with period/phase, asynchronous modules and per-module timing."""
from __future__ import annotations

import collections
import time
from concurrent.futures import ThreadPoolExecutor, wait

import numpy as np

from ..interrupt import is_interrupt
from ..module import Clock
from .buffers import alias_view
from .gating import gated
from .portguard import PortGuard
from .schedule import thread_groups


class AsyncModule:
    """Runs a module's tick in the background, at most one job at a time.

    The module works on private copies of its inputs (taken when a job starts) and outputs
    (published when the job has finished); while a job runs, the outputs keep their last
    finished values, and parameter changes and commands wait in a queue. The histories of
    its outputs (``rings``) advance only when a job is published, so a delay window holds
    the last finished values, each once.
    """

    def __init__(self, inst, inputs: dict, outputs: dict, clock: Clock):
        self.inst = inst
        self.module = inst.module
        self.shared_clock = clock
        self.module.clock = Clock(clock.tick_duration)
        # the module's own copies of its connected inputs and of its outputs, by port name
        self.private = {name: buf.array.copy()
                        for name, buf in list(inputs.items()) + list(outputs.items())
                        if buf.array is not None and buf.alias is None}
        for name, buf in outputs.items():       # an alias views its output's copy
            if buf.alias is not None:
                self.private[name] = self._private_alias(buf)
        self.inputs = [(buf.array, self.private[n]) for n, buf in inputs.items()
                       if buf.array is not None]
        self.outputs = [(buf.array, self.private[n]) for n, buf in outputs.items()
                        if buf.alias is None]
        self.executor = ThreadPoolExecutor(1, thread_name_prefix=f"ikaros-async-{inst.path}")
        self.future = None
        self.pending: collections.deque = collections.deque()
        self.completed = 0
        self.rings: list = []       # the histories of the outputs, pushed on publication

    def _private_alias(self, buf):
        target, index = buf.alias
        base = self.private.get(target.name)
        if base is None:                        # an alias of an alias
            base = self.private[target.name] = self._private_alias(target)
        return alias_view(base, index, buf.shape)[0]

    @property
    def running(self) -> bool:
        return self.future is not None and not self.future.done()

    def _publish(self) -> None:
        future, self.future = self.future, None
        error = future.exception()
        if error is not None:
            raise error
        for ring in self.rings:         # the value being replaced goes into the history
            ring.push()
        for public, private in self.outputs:
            np.copyto(public, private)
        self.completed += 1
        while self.pending:
            self.pending.popleft()()

    def publish_init(self) -> None:
        for public, private in self.outputs:
            np.copyto(public, private)

    def take_inputs(self) -> None:
        for public, private in self.inputs:
            np.copyto(private, public)

    def __call__(self) -> None:
        if self.future is not None:
            if not self.future.done():
                return
            self._publish()
        self.take_inputs()
        clock, mine = self.shared_clock, self.module.clock
        mine.tick, mine.time, mine.real_time = clock.tick, clock.time, clock.real_time
        mine.lag, mine.run = clock.lag, clock.run
        self.future = self.executor.submit(self.module.tick)

    def apply(self, change) -> None:
        """Apply a parameter change or command now, or after the running job."""
        if self.running:
            self.pending.append(change)
        else:
            change()

    def wait(self, report=None) -> None:
        """Wait for the running job and publish it, with the changes queued behind it (the
        state is saved, loaded or reset between jobs). A job or change that fails is
        reported by ``report`` (default: the module's fatal error, as in a tick)."""
        if self.future is not None:
            try:
                self.future.result()
                self._publish()
            except Exception as e:
                self.future = None
                (report or self.module.fatal_error)(f"{type(e).__name__}: {e}")

    def adopt_outputs(self) -> None:
        """The module's own copies of its outputs take the public values (after a state
        was loaded or reset), so its next job goes on from them."""
        for public, private in self.outputs:
            np.copyto(private, public)

    def finish(self) -> None:
        """Wait for the running job and publish it, with the changes queued behind it
        (before stop). A job or change that fails now is reported as the module's error."""
        self.wait(self.module.error)
        self.executor.shutdown(wait=True)


def _every(tick, period: int, phase: int, clock: Clock):
    def step():
        if clock.tick % period == phase:
            tick()
    return step


class Plan:
    """The calls of one tick, in schedule order, grouped per module.

    ``threads`` > 1 runs thread groups (modules joined by zero-delay connections) in
    parallel lanes; results are the same as with one thread, since lanes share no
    zero-delay data. ``cost(module)`` weighs modules when lanes are balanced. After the
    calls a PortGuard finds a module that replaced one of its port arrays (``ports``:
    portguard.port_attributes), among those whose Python tick runs.
    """

    def __init__(self, schedule: list, pre_tick: dict, tick_of: dict, edges: dict,
                 threads: int, cost, fuser=None, ports: list | None = None):
        self.schedule = schedule
        self.ports = ports or []
        self.index = {inst: i for i, inst in enumerate(schedule)}
        self.calls = {}
        for inst in schedule:
            copies = pre_tick.get(inst)
            self.calls[inst] = copies + [tick_of[inst]] if copies else [tick_of[inst]]
        result = fuser(self.calls) if fuser is not None and threads <= 1 else None
        if result is not None:
            self.sequence, self.owner, self.fused = result
        else:
            self.sequence = [c for inst in schedule for c in self.calls[inst]]
            self.owner = {c: inst for inst in schedule for c in self.calls[inst]}
            self.fused = {}
        self._watch()
        n = len(schedule)
        self.count = np.zeros(n, dtype=np.int64)
        self.total = np.zeros(n)
        self.max = np.zeros(n)
        self.profiling = False
        self.lanes: list[list] = []
        self.pool = None
        if threads > 1:
            groups = thread_groups(schedule, edges)
            if len(groups) > 1:
                lanes = [[] for _ in range(min(threads, len(groups)))]
                load = [0.0] * len(lanes)
                for group in sorted(groups, key=lambda g: -sum(cost(m) for m in g)):
                    k = load.index(min(load))
                    lanes[k].append(group)
                    load[k] += sum(cost(m) for m in group)
                self.lanes = [[m for group in lane for m in group] for lane in lanes]
                self.pool = ThreadPoolExecutor(len(self.lanes) - 1,
                                               thread_name_prefix="ikaros-lane")

    def adopt(self, sequence: list, owner: dict, fused: dict) -> None:
        """Use other calls for the tick from now on (the compiled plan made meanwhile)."""
        self.sequence, self.owner, self.fused = sequence, owner, fused
        self._watch()

    def _watch(self) -> None:
        """Guard the ports of the modules whose Python tick runs."""
        guard = PortGuard([(inst, ports) for inst, ports in self.ports
                           if inst not in self.fused])
        self.guard = guard if len(guard) else None

    def run(self) -> tuple | None:
        """Run one tick's calls. Returns (module, exception) for a failure, else None."""
        failure = self._run()
        if failure is None and self.guard is not None:
            return self.guard.check()
        return failure

    def _run(self) -> tuple | None:
        if self.pool is not None:
            return self._run_lanes()
        if self.profiling:
            return self._run_modules(self.schedule)
        step = None
        try:
            for step in self.sequence:
                step()
        except BaseException as e:
            if is_interrupt(e):
                raise
            # a compiled stretch names the member whose Python call failed
            return getattr(step, "failed", None) or self.owner.get(step), e
        return None

    def _run_modules(self, modules: list) -> tuple | None:
        perf = time.perf_counter
        for inst in modules:
            i = self.index[inst]
            start = perf()
            try:
                for call in self.calls[inst]:
                    call()
            except BaseException as e:
                if is_interrupt(e):
                    raise
                return inst, e
            if self.profiling:
                spent = perf() - start
                self.count[i] += 1
                self.total[i] += spent
                if spent > self.max[i]:
                    self.max[i] = spent
        return None

    def _run_lanes(self) -> tuple | None:
        futures = [self.pool.submit(self._run_modules, lane) for lane in self.lanes[1:]]
        failure = self._run_modules(self.lanes[0])
        wait(futures)
        for f in futures:
            failure = failure or f.result()
        return failure

    def refresh(self, inst) -> None:
        """A module's parameters changed: update a fused operation that holds them."""
        op = self.fused.get(inst)
        if op is not None:
            op.refresh(inst)

    def module_figures(self) -> list[dict]:
        """Per-module time: count, mean and max in seconds (while profiling was on)."""
        out = []
        for inst, i in self.index.items():
            c = int(self.count[i])
            out.append({"module": inst.path, "class": inst.entry.name, "count": c,
                        "mean": float(self.total[i] / c) if c else 0.0,
                        "max": float(self.max[i])})
        return out

    def close(self) -> None:
        if self.pool is not None:
            self.pool.shutdown(wait=True)
            self.pool = None


def module_tick(inst, clock: Clock):
    """A module's tick as the plan calls it: with period/phase and its first tick
    (module_start, start_tick) when they are set."""
    period, phase = inst.period, inst.phase
    tick = inst.module.tick
    return gated(tick if period == 1 else _every(tick, period, phase, clock), inst, clock)
