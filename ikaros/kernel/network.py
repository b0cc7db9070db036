"""A built network: buffers allocated once, a schedule, and the tick loop."""
from __future__ import annotations

import collections
import gc
import os
import sys
import time
from typing import Any

import numpy as np

from ..dynamic import DynamicArray
from ..closedpipe import print_line
from ..errors import ModelError, RunError
from ..interrupt import fault_text, is_interrupt, module_faults
from ..language.values import ValueError_, format_number, value_text
from ..language.writer import write_file
from .. import priority
from ..priority import PriorityError, PriorityRequest
from ..module import (END_OF_FILE, EXCEPTION, FATAL_ERROR, LEVEL_NAMES, PRINT, TERMINATE,
                      WARNING, Module, attribute_name, parameter_attribute)
from . import compiled
from .buffers import Run, alias_view
from .carry import rebuild
from .compiled.background import BackgroundPlan
from .compiled.plan import CompiledRun, compiled_gather, compiled_plan
from .control import PLAY, REALTIME, Controller
from .dynamic import DynamicRing, delayed_copy
from .execution import AsyncModule, Plan, module_tick
from .gating import gated
from .fusion import fuse
from .portguard import bound_ports, port_attributes, replaced_in_init
from .memory import Arena, BulkCopy, Ring, compile_copy, compile_ring_copy
from .firsttick import FIRST_TICK, empty_history
from .limits import check_memory as _check_memory
from .loadwarnings import module_warning
from .ranges import check_parameter, fit_shape
from .taps import OutputTap
from .topdefaults import DEFAULT_TICK_DURATION
from .threadpools import ThreadPools, parse_setting as parse_threadpool_setting
from .runfacts import RunFacts
from .timing import Timing
from .watchdog import Watchdog, task_timeout
from .scope import VariableError, from_python
from . import state as _state
from .state import capture_initial
from .tree import Group, ModuleInstance, find_component


def _bind_alias(buf) -> None:
    """An alias output's array: its view of the output it aliases (bound first)."""
    if buf.alias is None or buf.array is not None:
        return
    target, index = buf.alias
    _bind_alias(target)
    buf.array, start = alias_view(target.array, index, buf.shape)
    buf.offset = target.offset + start


def _live_array(buf) -> np.ndarray:
    """A buffer's array (an unconnected optional one has none: empty)."""
    return buf.array if buf.array is not None else np.zeros((0,), np.float32)


class Network:
    """A runnable model: the kernel's network. ``ikaros.load`` gives an ``ikaros.Network``,
    which adds what joins it to notebooks and recording.

    ``tick`` is the number of ticks completed. Modules see the first tick as tick
    ``first_tick``: 0 in an Ikaros 2 file, 1 in an Ikaros 3 file (``dialect``).
    """

    def __init__(self, builder, top: Group, order: list[ModuleInstance], runs: list[Run],
                 edges: dict):
        self.filename = builder.filename
        self.model = builder.model             # the model tree as read (saved by save())
        self.diagnostics = builder.diagnostics        # the load's settings and warnings
        self.warnings = builder.diagnostics.warnings   # load-time warnings (ModelWarning)
        self._overrides = builder.overrides
        self.user_data = builder.user_data      # kept when the model is built again
        self.limits = builder.limits
        self.builder_class = type(builder)      # what apply() builds the edited model with
        self.top = top
        self.clock = builder.clock
        self.schedule = order
        self.runs = runs
        self.zero_delay_edges = edges
        self.log: collections.deque = collections.deque(maxlen=1000)
        self.log.extend((0, PRINT, "", n.as_note()) for n in builder.diagnostics.notes)
        self.log.extend((0, WARNING, w.module or "", w.located()) for w in self.warnings)
        self.log_level = PRINT
        self.tick = 0
        self.dialect = builder.dialect          # "2" or "3": the file's Ikaros version
        self.first_tick = FIRST_TICK[self.dialect]     # what modules see on the first tick
        self._empty_history = None      # Ikaros 3: what the first tick sets to zero
        self._started = time.perf_counter()
        self.timing = Timing()
        self._controller: Controller | None = None
        self.stop_reason: tuple[int, str] | None = None
        self.stop_printed = False           # whether the stop reason has been printed
        self._stopped = False
        self._buffers = builder.buffers
        self.modules = {inst.path: inst for inst in order}
        self.clock.run = RunFacts(self)
        # Observers of the run (recordings): each must be quick and must not raise.
        self.parameter_hooks: list = []    # hook(path, value) after set_parameter
        self.close_hooks: list = []        # hook() when close() is called
        self._taps: list[OutputTap] = []   # add_tap(); the first is copied in the compiled tick
        self._tap_steps: list = []         # the others' steps, at the end of _delayed
        # whether the build froze the objects (gc.freeze), given back by close()
        self.frozen_objects = False
        # modules this network does not start or stop: those that take over from the
        # network it replaces (carry.py; not started until take_adopted), and those it
        # handed over to the network that replaced it (hand_over)
        self._adopting: dict = dict(getattr(builder, "adopting", None) or {})
        self._unowned: set = set(self._adopting)
        # until the modules' init has run, their warnings are model warnings (loadwarnings.py)
        self._loading = True
        notify = builder.notify = self.notify
        for inst in order:
            inst.module._ik_notify = notify
        self.clock.tick_duration = self._tick_duration()
        self.stop_tick = self._whole_number("stop", minimum=-1)
        self.threads = self._whole_number("threads", minimum=1)
        self.webui_port = self._whole_number("webui_port", minimum=1, maximum=65535)
        # Ikaros 2's -z: srand() of the C rand() stream the modules share, before any init
        seed = self._whole_number("random_seed", minimum=0, maximum=0xFFFFFFFF)
        if seed is not None:
            builder.c_random.seed(seed)
        self.task_timeout = task_timeout(self.top.attrs.get("task_timeout"),
                                         lambda m: self._setting_error("task_timeout", m))
        self._watchdog: Watchdog | None = None
        self.priority_request = self._priority_request()
        self.thread_pools = ThreadPools(self._thread_pool_setting())
        # before init, so that device threads the modules start there get the priority too
        priority.configure(self.priority_request)
        self.startup = builder.startup
        with self.startup.step("memory"):
            self._allocate()
        with self.startup.step("compile the tick"):
            self._compile()
        with self.startup.step("init of the modules"):
            self._init_modules()
        self._loading = False
        # what reset_state goes back to (the modules taken over: their own, from carry.py)
        self.initial_state = capture_initial(self, skip=self._unowned)
        self._check_checksum()
        if self.task_timeout:
            self._watchdog = Watchdog(self, self.task_timeout, Network._tick.__code__)

    # --- setup ---------------------------------------------------------------------------
    def _tick_duration(self) -> float:
        text = self.top.attrs.get("tick_duration")
        if text in (None, ""):
            return DEFAULT_TICK_DURATION[self.dialect]
        try:
            value = float(text)
        except ValueError:
            value = float("nan")
        if not np.isfinite(value) or value <= 0:
            raise self._setting_error("tick_duration", f'tick_duration "{text}" must be a '
                                      f'finite number of seconds > 0')
        return value

    def _setting_error(self, key: str, message: str):
        """An error in a top-group setting, blamed on the command line (or the keyword of
        ``ikaros.load``) when it was given there, else on the file."""
        if key in self._overrides:
            return ModelError(f"{message} (given on the command line)")
        return self.model.error(message)

    def _priority_request(self) -> PriorityRequest | None:
        attrs = self.top.attrs
        try:
            return PriorityRequest.parse(attrs.get("priority"), attrs.get("cpus"),
                                         attrs.get("lock_memory"))
        except PriorityError as error:
            key = str(error).partition("=")[0]
            raise self._setting_error(key, str(error)) from None

    def _thread_pool_setting(self) -> int | None:
        try:
            return parse_threadpool_setting(self.top.attrs.get("blas_threads"))
        except ValueError as error:
            raise self._setting_error("blas_threads", str(error)) from None

    def _whole_number(self, key: str, minimum: int, maximum: int | None = None) -> int | None:
        """A top-group setting that must be a whole number >= minimum (and <= maximum; None
        when unset)."""
        text = self.top.attrs.get(key)
        if text in (None, ""):
            return None
        stripped = text.strip().lstrip("+")
        if not (stripped.lstrip("-").isdigit() and minimum <= int(stripped)
                and (maximum is None or int(stripped) <= maximum)):
            bounds = f">= {minimum}" if maximum is None else f"from {minimum} to {maximum}"
            raise self._setting_error(key, f'{key}="{text}" must be a whole number {bounds}')
        return int(stripped)

    def _allocate(self) -> None:
        arena = Arena()
        self.arena = arena
        requests = []       # (buffer, request number in the arena)
        only_run: dict = {}         # an input's run, when it has just one
        several = set()             # inputs with more than one run
        deepest: dict = {}          # the longest delay read from an output, when >= 2
        for run in self.runs:
            target = run.target
            if target in only_run:
                several.add(target)
            else:
                only_run[target] = run
            if run.delay >= 2 and run.delay > deepest.get(run.source, 0):
                deepest[run.source] = run.delay
        self._shared = {}
        dynamic = []        # dynamic buffers: outside the arena
        for inst in self.schedule:
            inputs, outputs = self._buffers[inst]
            for buf in outputs.values():
                if buf.dynamic:
                    dynamic.append(buf)
                elif buf.alias is None:
                    requests.append((buf, arena.request(buf.shape)))
        for inst in self.schedule:
            inputs, _ = self._buffers[inst]
            for buf in inputs.values():
                if not buf.incoming:
                    continue
                run = only_run.get(buf)
                if run is not None and run.delay == 0 and buf not in several and run.whole:
                    self._shared[buf] = run.source
                elif buf.dynamic:
                    dynamic.append(buf)
                else:
                    requests.append((buf, arena.request(buf.shape)))
        _check_memory(arena, requests, deepest)
        arena.allocate()
        views, offsets = arena.views, arena.offsets
        for buf, k in requests:
            buf.array, buf.offset = views[k], offsets[k]
        for inst in self.schedule:
            for buf in self._buffers[inst][1].values():
                if buf.alias is not None:
                    _bind_alias(buf)
        for buf in dynamic:
            buf.dynamic_array = DynamicArray(buf.shape)
            buf.array = buf.dynamic_array.storage
        for buf, source in self._shared.items():
            buf.array, buf.offset = source.array.reshape(buf.shape), source.offset
            buf.dynamic_array = source.dynamic_array
        ring_arena = Arena()
        self.rings = {src: Ring(src.array, d - 1, ring_arena) for src, d in deepest.items()
                      if not src.dynamic}
        ring_arena.allocate()
        for ring in self.rings.values():
            ring.bind()
        self.ring_arena = ring_arena
        self.dynamic_rings = {src: DynamicRing(src.dynamic_array, d - 1)
                              for src, d in deepest.items() if d >= 2 and src.dynamic}
        self.async_modules: dict = {}
        for inst in self.schedule:
            inputs, outputs = self._buffers[inst]
            if inst.asynchronous:
                job = AsyncModule(inst, inputs, outputs, self.clock)
                self.async_modules[inst] = job
                for name, buf in list(inputs.items()) + list(outputs.items()):
                    setattr(inst.module, attribute_name(name), job.private.get(name))
                continue
            module = inst.module
            for ports in (inputs, outputs):
                for name, buf in ports.items():
                    setattr(module, attribute_name(name),
                            buf.array if buf.dynamic_array is None else buf.dynamic_array)

    def _compile(self) -> None:
        self._delayed = []
        bulk = BulkCopy(self.arena.block)
        pre_tick: dict = collections.defaultdict(list)
        for run in self.runs:
            if run.target in self._shared:
                continue
            if run.source.dynamic:
                self._delayed.append(delayed_copy(run.target.dynamic_array,
                                                  run.source.dynamic_array,
                                                  run.delay,
                                                  self.dynamic_rings.get(run.source)))
                continue
            dst = run.target.array
            if run.delay == 0:
                pre_tick[run.target.owner].append(
                    compile_copy(dst, run.dst_index, run.source.array, run.src_index))
            elif run.delay == 1:
                if bulk.accepts(dst, run.source.array, len(run.src_index)):
                    bulk.add(run.target.offset, run.dst_index, run.source.offset,
                             run.src_index)
                else:
                    self._delayed.append(
                        compile_copy(dst, run.dst_index, run.source.array, run.src_index))
            else:
                self._delayed.append(compile_ring_copy(dst, run.dst_index,
                                                       self.rings[run.source], run.delay,
                                                       run.src_index))
        bulk_copy = bulk.compile()
        if bulk_copy is not None:
            self._delayed.insert(0, bulk_copy)
        self._pre_tick = pre_tick
        # the histories of outputs of asynchronous modules advance when a job is published
        async_rings = set()
        for inst, job in self.async_modules.items():
            for buf in self._buffers[inst][1].values():
                ring = self.rings.get(buf) or self.dynamic_rings.get(buf)
                if ring is not None:
                    job.rings.append(ring)
                    async_rings.add(id(ring))
        self._ring_list = [ring for ring in list(self.rings.values()) +
                           list(self.dynamic_rings.values()) if id(ring) not in async_rings]
        if self.first_tick:
            self._empty_history = empty_history(self.runs, self._shared, self._ring_list)
        tick_of = {inst: module_tick(inst, self.clock) if inst not in self.async_modules
                   else gated(self.async_modules[inst], inst, self.clock)
                   for inst in self.schedule}
        block = self.arena.block
        minimum = self._compiled_minimum()
        self._background = None

        def fuser(calls):
            def make(cancelled=None):
                return compiled_plan(self.schedule, self.zero_delay_edges, self._buffers,
                                     self.runs, self._shared, block, calls, minimum,
                                     compiled.executor, cancelled)
            if minimum == compiled.AUTO_MINIMUM:     # auto: made while the network runs
                self._background = BackgroundPlan(make)
            elif minimum is not None:        # the compiled tick from the first tick
                result = make()
                if result is not None:
                    return result
            return fuse(self.schedule, self.zero_delay_edges, self._buffers, block, calls,
                        pre_tick)
        ports = port_attributes(self.schedule, self._buffers)
        self._port_attributes = dict(ports)
        self.plan = Plan(self.schedule, pre_tick, tick_of, self.zero_delay_edges,
                         self.threads or 1, self._module_cost, fuser, ports)
        self._bulk = bulk if bulk_copy is not None else None
        self.compiled_since = 0 if self.compiled_modules else None
        if self.compiled_since is not None:
            self._compiled_gather()

    def _compiled_gather(self) -> None:
        """The delay-1 copies of small buffers as an instruction of the compiled tick, with
        the first output tap's row; the other taps step with NumPy at the start of a tick."""
        for tap in self._taps:
            tap.unbind()
        compiled_tap = None
        if self._bulk is not None and self.compiled_since is not None:
            compiled_tap = self._taps[0] if self._taps else None
            self._delayed[0] = compiled_gather(self.arena.block, *self._bulk.indices(),
                                               compiled.executor(), compiled_tap,
                                               self.tick - 1)
        steps = [tap.step for tap in self._taps if tap is not compiled_tap]
        self._delayed[len(self._delayed) - len(self._tap_steps):] = steps
        self._tap_steps = steps

    def add_tap(self, index: np.ndarray, rows: np.ndarray, every: int,
                on_signal) -> OutputTap:
        """Keep the arena values at ``index`` in successive rows of ``rows`` (float32, one
        column per index) after every ``every``-th tick from the next one on, in the compiled
        tick when there is one; ``on_signal`` is called when the room given is full or asked
        for (see taps.py). Call it between ticks."""
        tap = OutputTap(self.arena.block, index, rows, self.tick, every, on_signal)
        self._taps.append(tap)
        self._compiled_gather()
        return tap

    def remove_tap(self, tap: OutputTap) -> None:
        """Stop a tap (the row of the tick just done is kept first). Call it between
        ticks."""
        tap.settle()
        tap.unbind()
        if tap in self._taps:
            self._taps.remove(tap)
            self._compiled_gather()

    def _background_plan(self) -> None:
        """Before a tick: start making the compiled plan in the background with the first
        tick that is not run in real time (so that it competes with ticks, never with a
        build, and never holds up a real-time tick: numba's start-up holds the GIL for up
        to tens of milliseconds at a time), and use it once ready."""
        background = self._background
        if not background.started:
            controller = self._controller
            if controller is None or controller.state != REALTIME:
                background.start()
        elif background.ready:
            self._take_compiled_plan()

    def _take_compiled_plan(self) -> None:
        """Between ticks: use the compiled plan made in the background."""
        background, self._background = self._background, None
        if background.error is not None:
            self.notify(WARNING, None, f"the compiled tick could not be made, so the NumPy "
                                       f"kernel runs: {fault_text(background.error)}")
        if background.result is None:
            return
        self.plan.adopt(*background.result)
        for inst in background.changed:
            self.plan.refresh(inst)
        self.compiled_since = self.tick
        self._compiled_gather()

    def _cancel_background(self) -> None:
        """The run has ended: a compiled plan still being made is not needed."""
        if self._background is not None:
            self._background.cancel()
            self._background = None

    def wait_compiled(self, timeout: float | None = None) -> int:
        """Wait until the compiled tick that ``compiled="auto"`` makes in the background
        (from the first tick, or from now) is ready (at most ``timeout`` seconds) and use it
        from the next tick; returns ``compiled_modules``. Call it between ticks (not from
        another thread while the network runs)."""
        background = self._background
        if background is not None:
            if not background.started:
                background.start()
            if background.wait(timeout):
                self._take_compiled_plan()
        return self.compiled_modules

    def _compiled_minimum(self) -> int | None:
        """The compiled tick's setting: the compilable modules it needs, or None (off)."""
        try:
            return compiled.minimum_modules(self.top.attrs.get("compiled"))
        except compiled.SettingError as e:
            raise self.model.error(str(e)) from None

    @property
    def compiled_modules(self) -> int:
        """How many modules run in the compiled tick (0 when it is off)."""
        return sum(1 for op in self.plan.fused.values() if isinstance(op, CompiledRun))

    def _module_cost(self, inst: ModuleInstance) -> int:
        """A module's weight when thread lanes are balanced: its output elements."""
        return 1 + sum(b.size for b in self._buffers[inst][1].values())

    def _init_modules(self) -> None:
        """Run every init in schedule order. When one fails, the modules already initialised
        are stopped (in order) before the error is raised; the failing one is not."""
        self.clock.tick = self.first_tick - 1
        started = []
        starting = [inst for inst in self.schedule if inst not in self._unowned]
        try:
            for inst in starting:
                inst.module._ik_before_init()
            for inst in starting:
                self._init_module(inst)
                # (an init that fails, by raising or by a fatal error, cleans up after itself)
                started.append(inst)
        except BaseException:
            # Devices opened by the modules initialised so far go to their safe state.
            self._stopped = True
            self._cancel_background()
            for job in self.async_modules.values():
                job.finish()
            self.plan.close()
            try:
                self._stop_modules(started)
            finally:
                initialised = set(started)
                for inst in starting:
                    if inst not in initialised:
                        inst.module._ik_not_initialised()
            raise

    def _init_module(self, inst: ModuleInstance) -> None:
        """Run one module's init, its zero-delay inputs filled first; ModelError naming the
        module when it fails."""
        for copy in self._pre_tick.get(inst, ()):
            copy()
        job = self.async_modules.get(inst)
        if job is not None:
            job.take_inputs()
        error = None
        ports = self._port_attributes[inst]
        bound = bound_ports(inst.module, ports)
        try:
            inst.module.init()
            replaced = replaced_in_init(inst.module, ports, bound)
            if replaced is not None:
                raise replaced
            if job is not None:
                job.publish_init()
        except module_faults() as e:
            if is_interrupt(e) or (isinstance(e, ModelError) and e.filename is not None):
                raise
            error = inst.node.error(f"init failed: {fault_text(e)}")
        if error is None and self.stop_reason and self.stop_reason[0] == FATAL_ERROR:
            error = inst.node.error(f"While initializing module {inst.path}: "
                                    f"{self.stop_reason[1]}")
        if error is not None:
            raise error from None

    # --- taking over from a replaced network (carry.py) ------------------------------------
    def take_adopted(self) -> dict:
        """{instance: the replaced network's instance} of the modules left to take over
        from it (each once): the caller hands each its state, or starts it (start_late).
        From then on this network stops them when it ends."""
        adopting, self._adopting = self._adopting, {}
        self._unowned.difference_update(adopting)
        return adopting

    def start_late(self, inst: ModuleInstance) -> None:
        """Start a module that was left to take over and could not: its init now, as at
        load. When it fails, the run ends with that error."""
        inst.module._ik_before_init()
        try:
            self._init_module(inst)
        except ModelError as e:
            inst.module._ik_not_initialised()
            self._unowned.add(inst)           # never started: not stopped
            self.notify(FATAL_ERROR, inst.path, e.reason)
            return
        self.initial_state.update(capture_initial(self, scope=inst.path))

    def hand_over(self, inst: ModuleInstance) -> None:
        """``inst`` goes on in the network that replaced this one: this one does not stop
        it."""
        self._unowned.add(inst)

    def _check_checksum(self) -> None:
        if self.top.attrs.get("check_sum") not in (None, ""):
            # Ikaros 3's check sum weighs the original's own partition of the schedule
            # into task sequences, which this kernel does not make; it is not computed.
            self.notify(PRINT, None, f'check_sum="{self.top.attrs["check_sum"]}" (Ikaros 3) '
                                     f'is not verified: it depends on how the original '
                                     f'partitions its tasks')
        text = self.top.attrs.get("checksum")
        if text in (None, ""):
            return
        product = 1
        for inst in self.schedule:
            for buf in self._buffers[inst][1].values():
                product *= buf.size
        if str(product) == text.strip():
            self.notify(PRINT, None, f"Checksum match ({product}).")
            self.checksum_ok = True
        else:
            self.notify(EXCEPTION, None, f"Checksum mismatch: got {product} != {text}")
            self.checksum_ok = False

    # --- notifications -------------------------------------------------------------------
    def notify(self, level: int, module, message: str) -> None:
        """Receive a notification from a module (or the kernel when ``module`` is None)."""
        where = module if isinstance(module, str) else getattr(module, "path", "") or ""
        if level == WARNING and self._loading and isinstance(module, Module):
            record = module_warning(self.diagnostics, module, message)
            if record is not None:
                self.log.append((self.tick, level, where, record.located()))
            return
        self.log.append((self.tick, level, where, message))
        if level in (FATAL_ERROR, END_OF_FILE, TERMINATE) and (
                self.stop_reason is None or
                (level == FATAL_ERROR and self.stop_reason[0] != FATAL_ERROR)):
            self.stop_reason = (level, message)      # a fatal error wins over a clean end
            self._stop_where = where
            self.stop_printed = level <= self.log_level
        if level <= self.log_level:
            text = f"{where}: {message}" if where else message
            # one write per line, so that lines printed by other threads are not mixed in
            if level == PRINT:
                if not print_line(text) and self.stop_reason is None:
                    self.stop_reason = (TERMINATE, "standard output closed")
            else:
                print(f"{LEVEL_NAMES[level].replace('_', ' ')}: {text}\n", end="",
                      file=sys.stderr, flush=True)

    def time_out(self, where: str, warning: str, reason: str) -> None:
        """The watchdog found a tick too long: warn now, and end the run with ``reason``
        (a fatal error) when the tick has finished."""
        self.notify(WARNING, None, warning)
        self.log.append((self.tick, FATAL_ERROR, where, reason))
        if self.stop_reason is None or self.stop_reason[0] != FATAL_ERROR:
            self._stop_where = where
            self.stop_reason = (FATAL_ERROR, reason)
            self.stop_printed = False

    # --- running -------------------------------------------------------------------------
    @property
    def stopped(self) -> bool:
        """True once the run has ended (end of file, a fatal error, or close)."""
        return self._stopped

    def _tick(self) -> None:
        if self._background is not None:
            self._background_plan()
        for copy in self._delayed:
            copy()
        for ring in self._ring_list:
            ring.push()
        if not self.tick and self._empty_history is not None:
            self._empty_history()       # Ikaros 3: init values do not travel
        clock = self.clock
        clock.tick = number = self.tick + self.first_tick
        clock.time = number * clock.tick_duration
        start = time.perf_counter()
        clock.real_time = start - self._started
        failure = self.plan.run()
        if failure is not None:
            inst, error = failure
            self.notify(FATAL_ERROR, inst.path if inst else "kernel",
                        f"{fault_text(error)}")
        self.tick += 1
        self.timing.tick_done(time.perf_counter() - start)
        if self.stop_reason is not None:
            self._end()

    def _end(self) -> None:
        """End the run after the current tick: call every module's stop once."""
        if not self._stopped:
            self._stopped = True
            if self._watchdog is not None:
                self._watchdog.close()
            self._cancel_background()
            for job in self.async_modules.values():
                job.finish()
            self.plan.close()
            self._stop_modules([inst for inst in self.schedule if inst not in self._unowned])
        level, message = self.stop_reason or (TERMINATE, "closed")
        if level == FATAL_ERROR:
            where = getattr(self, "_stop_where", "")
            raise RunError(f"{where}: {message}" if where else message,
                           printed=self.stop_printed)

    def _stop_modules(self, modules: list[ModuleInstance]) -> None:
        """Call stop() of each module once. A stop() that fails is a fatal error (the run
        ends with an error); neither a failure nor a Ctrl-C in one skips the others
        (drivers put their hardware in a safe state there). A Ctrl-C is raised again
        after."""
        interrupted = None
        for inst in modules:
            try:
                inst.module.stop()
            except module_faults() as e:
                if is_interrupt(e):
                    interrupted = e
                    continue
                self.notify(FATAL_ERROR, inst.path, f"stop failed: {fault_text(e)}")
            except KeyboardInterrupt as e:
                interrupted = e
        if interrupted is not None:
            raise interrupted

    def _check_running(self) -> None:
        if self._stopped:
            level, message = self.stop_reason or (TERMINATE, "closed")
            raise RunError(f"the run has ended ({LEVEL_NAMES.get(level, level)}: {message})")

    def step(self) -> None:
        """Run exactly one tick."""
        self._check_running()
        self.clock.lag = 0.0
        self._tick()
        if self._controller is not None:
            for hook in self._controller.tick_hooks:
                hook()

    def run(self, ticks: int | None = None, real_time: bool = False):
        """Run ``ticks`` more ticks (as fast as possible, or on the tick_duration time base
        with ``real_time``). Without ``ticks``, run until the model's ``stop`` tick, end of
        file or an error. Returns ``tick``, the ticks completed so far. (``ikaros.Network``
        adds recording and a progress bar in a notebook.)"""
        self._check_running()
        return self.controller.run(REALTIME if real_time else PLAY, ticks)

    @property
    def controller(self) -> Controller:
        """The run modes and requests between ticks (shared by the CLI and the web UI)."""
        if self._controller is None:
            self._controller = Controller(self)
        return self._controller

    @property
    def profiling(self) -> bool:
        """Whether per-module times are measured (off by default: it costs a little)."""
        return self.plan.profiling

    @profiling.setter
    def profiling(self, on: bool) -> None:
        self.plan.profiling = bool(on)

    def figures(self) -> dict:
        """Timing figures: state, tick, elapsed time, ticks per second, actual tick
        duration, lag now/max/99th percentile, CPU usage, idle fraction."""
        return self.controller.figures()

    def module_figures(self) -> list[dict]:
        """Per-module time (count, mean, max in seconds) measured while profiling."""
        return self.plan.module_figures()

    def profile_text(self) -> str:
        """The timing figures and the per-module table, as printed by ``ikaros -p``."""
        f = self.figures()
        ms = 1000.0
        lines = [f"Ticks: {f['tick']} in {f['elapsed']:.3f} s ({f['ticks_per_second']:.1f} "
                 f"ticks/s); tick duration {f['tick_duration'] * ms:.3f} ms, actual "
                 f"{f['actual_tick_duration'] * ms:.3f} ms",
                 f"Lag: now {f['lag'] * ms:.3f} ms, max {f['lag_max'] * ms:.3f} ms, 99th "
                 f"percentile {f['lag_p99'] * ms:.3f} ms; resynchronised {f['resyncs']} times",
                 f"CPU usage: {f['cpu_usage'] * 100:.1f} % of {f['cpu_cores']} cores; idle: "
                 f"{f['idle'] * 100:.1f} %",
                 ""]
        rows = sorted(self.module_figures(), key=lambda m: -m["mean"])
        wm = max([32] + [len(m["module"]) for m in rows])     # long names widen the column
        wc = max([16] + [len(m["class"]) for m in rows])
        lines.append(f"{'module':{wm}} {'class':{wc}} {'count':>8} {'mean ms':>10} "
                     f"{'max ms':>10}")
        for m in rows:
            lines.append(f"{m['module']:{wm}} {m['class']:{wc}} {m['count']:>8} "
                         f"{m['mean'] * ms:>10.4f} {m['max'] * ms:>10.4f}")
        return "\n".join(lines)

    def close(self) -> None:
        """End the run: every module's stop() is called once. A stop() that fails is
        reported and makes ``stop_reason`` a fatal error. The objects of a large build
        go back to the garbage collector (see ``frozen_objects``)."""
        for hook in self.close_hooks:
            hook()
        self.close_hooks.clear()
        if not self._stopped:
            self.stop_reason = self.stop_reason or (TERMINATE, "closed")
            try:
                self._end()
            except RunError:
                pass            # reported; a failed stop() leaves stop_reason fatal
        if self.frozen_objects:
            self.frozen_objects = False
            gc.unfreeze()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    # --- access by path ------------------------------------------------------------------
    def _component(self, path: str, what: str):
        comp_path, _, name = path.rpartition(".")
        comp = self.top if comp_path == "" else find_component(self.top, comp_path)
        if comp is None or not name:
            raise KeyError(f'no {what} "{path}" in {self.top.name}')
        return comp, name

    def buffer_array(self, path: str) -> np.ndarray:
        """The live array of a module output or input (not a copy; do not write to it).
        Of a dynamic buffer, the whole capacity."""
        return _live_array(self._buffer(path))

    def _buffer(self, path: str):
        comp, name = self._component(path, "output or input")
        if isinstance(comp, ModuleInstance):
            inputs, outputs = self._buffers[comp]
            buf = outputs.get(name) or inputs.get(name)
            if buf is not None:
                return buf
        raise KeyError(f'no output or input "{path}" in {self.top.name}')

    def ports(self, module: str) -> tuple[list, list]:
        """The input and output declarations (InputSpec, OutputSpec) of a module, including
        ports it added in ``configure``."""
        inst = self.modules.get(module) or find_component(self.top, module)
        if not isinstance(inst, ModuleInstance):
            raise KeyError(f'no module "{module}" in {self.top.name}')
        return list(inst.module._ik_inputs.values()), list(inst.module._ik_outputs.values())

    def output(self, path: str) -> np.ndarray:
        """A copy of a module output (or input) as computed in the last completed tick (of
        a dynamic one, its current shape and values)."""
        buf = self._buffer(path)
        if buf.dynamic_array is not None:
            return buf.dynamic_array.data.copy()
        return _live_array(buf).copy()

    def parameter(self, path: str) -> Any:
        """The current value of a module parameter (or a group attribute, as text)."""
        comp, name = self._component(path, "parameter")
        if isinstance(comp, ModuleInstance) and name in comp.values:
            value = getattr(comp.module, parameter_attribute(name))
            return value.copy() if isinstance(value, np.ndarray) else value
        if isinstance(comp, Group) and name in comp.attrs:
            return comp.attrs[name]
        raise KeyError(f'no parameter "{path}" in {self.top.name}')

    def set_parameter(self, path: str, value: Any) -> None:
        """Set a module parameter; it takes effect from the next tick. Text is read as in a
        model file; a bad value raises ValueError and changes nothing."""
        comp, name = self._component(path, "parameter")
        if not isinstance(comp, ModuleInstance) or name not in comp.values:
            raise KeyError(f'no parameter "{path}" in {self.top.name}')
        spec = comp.module.description.parameter(name)
        if spec.fixed:
            raise ValueError(f'parameter "{path}" is fixed while the model runs (the module '
                             f'uses it when it starts); change it in the model file')
        try:
            new = from_python(value, spec)
            if spec.shape:              # a fixed shape: the one the model gave it
                new = fit_shape(new, comp.values[name].shape)
            check_parameter(new, spec)
        except (ValueError_, VariableError, ValueError, TypeError) as e:
            raise ValueError(f'bad value for parameter "{path}": {e}') from None
        def change():
            attribute = parameter_attribute(name)
            old = getattr(comp.module, attribute)
            if isinstance(old, np.ndarray) and isinstance(new, np.ndarray) and \
                    old.shape == new.shape:
                old[...] = new
            else:
                setattr(comp.module, attribute, new)
        self._apply(comp, change)
        self._refresh(comp)
        comp.values[name] = new
        comp.has_value[name] = True
        comp.node.attrs[name] = value if isinstance(value, str) else value_text(new)
        for hook in self.parameter_hooks:
            hook(path, comp.node.attrs[name])

    def command(self, path: str, name: str, x: float = 0, y: float = 0,
                value: Any = None) -> None:
        """Call a module's command(name, x, y, value)."""
        comp = find_component(self.top, path)
        if not isinstance(comp, ModuleInstance):
            raise KeyError(f'no module "{path}" in {self.top.name}')
        self._apply(comp, lambda: comp.module.command(name, x, y, value))
        self._refresh(comp)                     # a command may set parameters

    def _refresh(self, inst: ModuleInstance) -> None:
        """A module's parameters changed: update the plans that hold them."""
        background = self._background
        if background is not None:
            background.changed.add(inst)
        self._apply(inst, lambda: self.plan.refresh(inst))

    def _apply(self, inst: ModuleInstance, change) -> None:
        """Change a module now, or after its running asynchronous job."""
        job = self.async_modules.get(inst)
        if job is None:
            change()
        else:
            job.apply(change)

    def apply(self, model) -> "Network":
        """The network of ``model`` (an ``ikaros.Group``, or a model tree) taking over from
        this one, as the editor's Apply does: modules that did not change go on with their
        state (not started again; what they hold of their ports follows the new ones, see
        kernel/carry.py) and the run goes on from this tick; this network is closed. When
        ``model`` does not build, ModelError is raised and this network is unchanged.
        Returns the new network."""
        tree, classes = model.model_tree() if hasattr(model, "model_tree") else (model, None)
        return rebuild(self, tree, classes)

    def save(self, filename: str) -> None:
        """Write the model back as .ikg; loading it gives the same network."""
        write_file(self.model, filename)

    # --- state (kernel/state.py) ----------------------------------------------------------
    def state_file(self) -> str:
        """The default state file: ``model.state`` beside ``model.ikg``."""
        stem = os.path.splitext(os.path.abspath(self.filename or "model"))[0]
        return stem + ".state"

    def save_state(self, filename: str | None = None, scope: str | None = None) -> dict:
        """Write the state (outputs, delay lines, declared state, tick) of the network, or
        of the module or group ``scope``, to ``filename`` (default ``state_file()``), as
        ``ikaros -W`` does at the end of a run. Returns the file's header. Call it between
        ticks; raises StateError (a ValueError) or OSError."""
        filename = filename or self.state_file()
        header = _state.save(self, filename, scope)
        self.notify(PRINT, None, f"Saved state to {filename} ({header['item_count']} items, "
                                 f"tick {header['tick']})")
        return header

    def load_state(self, filename: str | None = None, scope: str | None = None) -> dict:
        """Read a state file (default ``state_file()``) into the network, or into the
        module or group ``scope``, as ``ikaros -L`` does after init. Every item is checked
        before anything changes; raises StateError naming what does not fit."""
        filename = filename or self.state_file()
        header = _state.load(self, filename, scope)
        self.notify(PRINT, None, f"Loaded state from {filename} (tick {self.tick})")
        return header

    def reset_state(self, scope: str | None = None) -> None:
        """Put the network (tick 0), or the module or group ``scope``, back to the state
        right after init."""
        _state.reset(self, scope)

    # --- description ---------------------------------------------------------------------
    def info(self) -> str:
        """Modules, connections, buffers with shapes, and the schedule, as text."""
        lines = [f"Model: {self.filename}", f"Top group: {self.top.name}", "", "Modules:"]
        for inst in sorted(self.schedule, key=lambda m: m.order):
            lines.append(f"  {inst.path} ({inst.entry.name})")
            inputs, outputs = self._buffers[inst]
            for kind, bufs in (("input", inputs), ("output", outputs)):
                for name, buf in bufs.items():
                    shape = "unconnected" if kind == "input" and not buf.incoming else \
                        "x".join(map(str, buf.shape)) or "scalar"
                    if buf.dynamic:
                        shape = f"dynamic, capacity {shape}"
                    shared = " (shares its source's memory)" if buf in self._shared else ""
                    private = kind == "output" and inst.module._ik_outputs[name].private
                    lines.append(f"    {'state' if private else kind} {name}: {shape}{shared}")
        lines += ["", "Connections:"]
        for run in self.runs:
            lines.append(f"  {run.source.path} -> {run.target.path} delay {run.delay} "
                         f"({len(run.src_index)} elements)")
        lines += ["", "Schedule:"]
        for i, inst in enumerate(self.schedule):
            lines.append(f"  {i + 1}. {inst.path}")
        lines.append("")
        lines.append(f"Memory: {format_number(self.arena.nbytes + self.ring_arena.nbytes)} "
                     f"bytes of buffers")
        pending = (" (compiled=\"auto\": made in the background once the model ticks, not "
                   "in real time, when at least 64 modules can be compiled)"
                   if self._background is not None else "")
        lines.append(f"Compiled tick: {self.compiled_modules} of {len(self.schedule)} modules"
                     f"{pending}")
        return "\n".join(lines)

