"""Groups that run in other kernel processes: ``<group name="Vision" process="worker">``.

Every process builds the whole model from the same file (so sizes, parameters, variables and
the schedule are the same everywhere) but runs, initialises and stops only its own modules:
the main process everything outside the process groups, each worker one group. Connections
that cross a group's boundary must have a delay of at least 1; their source arrays travel
over the link once per tick, in step, so every input sees exactly the values it sees in one
process. Tick n in the main process:

1. send each worker the values of tick n-1 of the sources outside it that it reads;
2. run its own modules for tick n while every worker runs its group's tick n;
3. receive from each worker its sources of tick n that others read.

The local copies of the other processes' source arrays feed the kernel's usual delay copies
and rings, so delays are kept in ticks.
"""
from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import RunError
from ..hardware.link.wire import LinkError
from ..kernel.network import Network
from ..kernel.scope import VariableError, substitute
from ..kernel.tree import Group, find_component
from ..module import EXCEPTION, FATAL_ERROR
from .atomic import SignalHold
from .workerlink import WorkerLink, stall_seconds


def process_groups(top: Group) -> dict[Group, str]:
    """{group: where it runs} for every group with a (non-empty) ``process`` attribute."""
    groups = {}
    for c in top.walk():
        if isinstance(c, Group) and c.attrs.get("process"):
            try:
                where = substitute(c.attrs["process"], c.parent).strip()
            except VariableError as e:
                raise c.node.error(f"process: {e}") from None
            if where:
                groups[c] = where
    return groups


def make_network(builder, top, order, runs, edges, *, single: type | None = None,
                 split: type | None = None) -> Network:
    """A Network (of the class ``single``), or a SplitNetwork (of the class ``split``, a
    subclass of it) when some group has a ``process`` attribute."""
    groups = process_groups(top)
    if not groups:
        return (single or Network)(builder, top, order, runs, edges)
    return (split or SplitNetwork)(builder, top, order, runs, edges, groups)


def process_group(inst, groups) -> Group | None:
    """The process group a module runs in (None: the main process)."""
    for c in inst.chain():
        if c in groups:
            return c
    return None


def crossings(runs, groups, group) -> tuple[list, list]:
    """(sources ``group``'s modules read from other processes, sources of ``group`` that
    other processes read), each a list of output buffers sorted by path. A crossing
    connection with delay 0 is a build error naming it."""
    incoming, outgoing = {}, {}
    for run in runs:
        src, dst = process_group(run.source.owner, groups), process_group(run.target.owner,
                                                                          groups)
        if src is dst:
            continue
        if run.delay == 0:
            where = next(g for g in (dst, src) if g is not None)
            raise run.node.error(
                f'the connection {run.source.path} -> {run.target.path} crosses into or out '
                f'of group "{where.path}", which runs in another process '
                f'(process="{groups[where]}"), with delay 0: a connection between '
                f'processes needs a delay of at least 1')
        if dst is group:
            incoming[run.source.path] = run.source
        elif src is group:
            outgoing[run.source.path] = run.source
    return ([incoming[k] for k in sorted(incoming)], [outgoing[k] for k in sorted(outgoing)])


class PartNetwork(Network):
    """A network that runs only the modules of one process (``group``; None: the main
    process) of a model split by ``process`` attributes."""

    def __init__(self, builder, top, order, runs, edges, groups, group):
        self.process_groups = groups
        self.process = group
        for g in groups:
            if any(p in groups for p in list(g.chain())[1:]):
                raise g.node.error(f'group "{g.path}" has a process attribute inside a group '
                                   f'that has one: process groups can not be nested')
        self.all_modules = order
        super().__init__(builder, top, order, runs, edges)

    def _compile(self) -> None:
        self.schedule = [inst for inst in self.all_modules
                         if process_group(inst, self.process_groups) is self.process]
        super()._compile()

    def _check_checksum(self) -> None:
        owned, self.schedule = self.schedule, self.all_modules
        try:
            if self.process is None:
                super()._check_checksum()
        finally:
            self.schedule = owned


class SplitNetwork(PartNetwork):
    """The main process of a split model: runs what is outside the process groups and
    drives one worker per group, tick by tick."""

    def __init__(self, builder, top, order, runs, edges, groups):
        self.workers = [WorkerLink(g, where, *crossings(runs, groups, g))
                        for g, where in groups.items()]
        self._hold = SignalHold()           # link messages whole through a Ctrl-C
        self._closing = False               # close() called: the run is being ended
        for worker in self.workers:
            worker.hold = self._hold
        self._source_text = builder._text
        self._load_request = {"type": "load", "filename": builder.filename,
                              "overrides": builder.overrides,
                              "strict": builder.diagnostics.strict,
                              "lenient": builder.diagnostics.lenient}
        super().__init__(builder, top, order, runs, edges, groups, None)

    def _compile(self) -> None:
        text = self._source_text
        if text is None:
            with open(self.filename, encoding="utf-8") as f:
                text = f.read()
        self._hold.install()
        try:
            for worker in self.workers:          # they build while this process does
                worker.stall_seconds = stall_seconds(worker.group, self.clock.tick_duration)
                worker.start(dict(self._load_request, text=text))
            super()._compile()
        except BaseException:
            self._stop_workers()
            raise

    def _init_modules(self) -> None:
        try:
            super()._init_modules()
            for worker in self.workers:
                self._relay(worker.ready(), self.tick)
        except BaseException:
            self._stop_workers()
            raise

    def _tick(self) -> None:
        for worker in self.workers:
            worker.send_tick(self.tick)
        super()._tick()             # may end the run, which collects the workers' tick
        self._collect()
        if self.stop_reason is not None and not self._stopped:
            self._end()

    def _collect(self) -> None:
        """Take each worker's answer to the tick sent to it and not yet answered (also
        after a Ctrl-C that came at any point of the tick)."""
        for worker in self.workers:
            tick = worker.pending
            if tick is None:
                continue
            try:
                log = worker.receive_tick()
            except LinkError as e:
                if self._closing:       # ended (Ctrl-C): a worker gone is no news
                    continue
                log = [(FATAL_ERROR, worker.group.path, str(e))]
            self._relay(log, tick)

    def _relay(self, log: list, tick: int) -> None:
        """Log (and print, and act on) a worker's notifications of ``tick``."""
        for level, where, message in log:
            self.notify(level, where, message)
            self.log[-1] = (tick, level, where, message)   # the tick they were made in

    def _worker_of(self, path: str) -> "WorkerLink | None":
        inst = find_component(self.top, path)
        group = process_group(inst, self.process_groups) if inst is not None else None
        return next((w for w in self.workers if w.group is group), None) if group else None

    def buffer_array(self, path: str) -> np.ndarray:
        """The live array of a module output or input; one of a module in a worker is
        brought over after every tick from now on (as the web UI's views need)."""
        array = super().buffer_array(path)
        worker = self._worker_of(path.rpartition(".")[0])
        if worker is not None and array.size:
            worker.watched.setdefault(path, array)
        return array

    def set_parameter(self, path: str, value: Any) -> None:
        """Set a parameter; one of a module in a worker is set there too, before its next
        tick (as here)."""
        super().set_parameter(path, value)
        worker = self._worker_of(path.rpartition(".")[0])
        if worker is not None:
            worker.requests.append(["set", path, _plain(value)])

    def command(self, path: str, name: str, x: float = 0, y: float = 0,
                value: Any = None) -> None:
        """A command to a module; one in a worker is sent there, before its next tick."""
        worker = self._worker_of(path)
        if worker is None:
            super().command(path, name, x, y, value)
        else:
            worker.requests.append(["command", path, name, x, y, _plain(value)])

    def close(self) -> None:
        self._closing = True
        super().close()

    def _end(self) -> None:
        try:
            self._collect()
            super()._end()
        finally:
            self._stop_workers()

    def _stop_workers(self) -> None:
        try:
            for worker in self.workers:
                worker.stop()
        finally:
            self._hold.uninstall()


def _plain(value: Any) -> Any:
    """A parameter value or command argument as JSON can carry it."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    return value


def worker_network(group_path: str, incoming: list, outgoing: list):
    """A network factory for ``ikaros worker``: runs only the group at ``group_path``, and
    checks that the crossings are those the main process announced."""
    def make(builder, top, order, runs, edges):
        groups = process_groups(top)
        mine = next((g for g in groups if g.path == group_path), None)
        if mine is None:
            raise RunError(f'the model has no group "{group_path}" with a process attribute')
        net = WorkerNetwork(builder, top, order, runs, edges, groups, mine)
        if [b.path for b in net.incoming] != incoming or \
                [b.path for b in net.outgoing] != outgoing:
            net.close()
            raise RunError("the model built here differs from the main process's: not the "
                           "same connections cross the group's boundary")
        return net
    return make


class WorkerNetwork(PartNetwork):
    """A worker's network: runs one process group, fed by the link. Its notifications are
    kept in ``outbox`` for the main process (which prints them), not printed here."""

    def __init__(self, builder, top, order, runs, edges, groups, group):
        self.incoming, self.outgoing = crossings(runs, groups, group)
        self.outbox: list = []
        super().__init__(builder, top, order, runs, edges, groups, group)

    @property
    def log_level(self) -> int:
        return 0            # nothing is printed here: the main process prints the outbox

    @log_level.setter
    def log_level(self, level: int) -> None:
        pass

    def notify(self, level: int, module, message: str) -> None:
        super().notify(level, module, message)
        where = module if isinstance(module, str) else getattr(module, "path", "") or ""
        self.outbox.append([level, where, message])

    def take_log(self) -> list:
        log, self.outbox = self.outbox, []
        return log

    def apply(self, requests: list) -> None:
        """Parameter changes and commands from the main process, before a tick."""
        for request in requests:
            try:
                if request[0] == "set":
                    self.set_parameter(request[1], request[2])
                elif request[0] == "command":
                    self.command(*request[1:])
            except Exception as e:       # reported to the main process; the run goes on
                self.notify(EXCEPTION, request[1], f"{request[0]} failed: "
                                                   f"{type(e).__name__}: {e}")

    def take(self, arrays: list) -> None:
        if len(arrays) != len(self.incoming):
            raise LinkError(f"{len(arrays)} arrays came where {len(self.incoming)} were due")
        for buf, a in zip(self.incoming, arrays):
            buf.array[...] = a.reshape(buf.shape)

    def sources(self, watched=()) -> list:
        """The arrays for the main process: the sources it reads, then the buffers it
        watches (0 for a path that is not here)."""
        arrays = [b.array for b in self.outgoing]
        for path in watched:
            try:
                arrays.append(self.buffer_array(path))
            except KeyError:
                arrays.append(np.zeros(0, np.float32))
        return arrays
