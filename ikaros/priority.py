"""Scheduling priority for real-time runs (Linux).

A run may ask (top-group ``priority``, ``cpus`` and ``lock_memory``; ``ikaros --priority``)
for its tick thread and the threads that talk to devices to run under a real-time scheduling
policy (``SCHED_FIFO`` or ``SCHED_RR``), or failing that at the best ``nice`` value the
process may take, pinned to chosen cores, with the process's memory locked. The other threads
of ikaros (the recorder's writer) then run below them, and the threads that run Python code
often while the ticks run (the web UI's server and image encoder) under the real-time policy
just below them. What was granted
and what was refused is kept in :func:`report`; nothing is changed for a run that does not ask.

One request holds per process. The kernel calls :func:`configure` when a network is built and
:func:`tick_thread` in the thread that runs the ticks; drivers call :func:`device_thread` in
their I/O threads, the recorder calls :func:`background_thread` in its writer and the web UI
:func:`below_tick_thread` in its server and image encoder, in any order: a thread registered before the request is given its priority when the request
comes.
"""
from __future__ import annotations

import ctypes
import ctypes.util
import os
import resource
import sys
import threading
from dataclasses import dataclass, field

POLICIES = {"fifo": "SCHED_FIFO", "rr": "SCHED_RR"}
# below the 50 that Linux gives its threaded interrupt handlers (serial ports, USB)
DEFAULT_RT_PRIORITY = 40
DEFAULT_NICE = -10
BACKGROUND_NICE = 5             # background threads, below the tick when it asks
BELOW_TICK = 10                 # real-time levels between the tick and a below_tick_thread
OFF = ("", "no", "off", "none", "false", "0")

_RTPRIO_HELP = ("run as root, give the interpreter the capability (sudo setcap "
                "cap_sys_nice+ep {python}), or allow real-time priorities to your user "
                "(`ulimit -r 99`; for good: a line `USER - rtprio 99` in "
                "/etc/security/limits.conf)")
_NICE_HELP = ("run as root, give the interpreter CAP_SYS_NICE, or allow a lower nice "
              "(`ulimit -e 40`; for good: `USER - nice -20` in /etc/security/limits.conf)")
_MEMLOCK_HELP = ("run as root, or allow locking all memory (`ulimit -l unlimited`; for good: "
                 "`USER - memlock unlimited` in /etc/security/limits.conf)")


class PriorityError(ValueError):
    """A priority setting that cannot be read (the message names the setting)."""


@dataclass(frozen=True)
class PriorityRequest:
    """What a run asks for: a policy (``fifo``, ``rr``, ``nice`` or None), its level (1..99
    for the real-time policies, -20..19 for nice), the cores, and whether to lock memory."""
    policy: str | None = None
    level: int = 0
    cpus: tuple[int, ...] | None = None
    lock_memory: bool = False

    def __str__(self) -> str:
        parts = []
        if self.policy:
            parts.append(f"{self.policy}:{self.level}")
        if self.cpus is not None:
            parts.append("cores " + ",".join(map(str, self.cpus)))
        if self.lock_memory:
            parts.append("memory locked")
        return ", ".join(parts)

    @classmethod
    def parse(cls, priority: str | None, cpus: str | None = None,
              lock_memory: str | None = None) -> "PriorityRequest | None":
        """The request of the settings' texts; None when nothing is asked for."""
        policy, level = _parse_policy((priority or "").strip().lower())
        cores = _parse_cpus(cpus)
        text = (lock_memory or "").strip().lower()
        if text in ("", "default"):
            lock = policy in POLICIES          # a real-time request locks memory too
        elif text in ("yes", "true", "1", "on"):
            lock = True
        elif text in OFF:
            lock = False
        else:
            raise PriorityError(f'lock_memory="{lock_memory}" must be yes or no')
        if policy is None and cores is None and not lock:
            return None
        return cls(policy, level, cores, lock)


def _parse_policy(text: str) -> tuple[str | None, int]:
    if text in OFF:
        return None, 0
    name, _, level_text = text.partition(":")
    if name in ("realtime", "yes", "on", "true", "1"):
        name = "fifo"
    if name not in ("fifo", "rr", "nice"):
        raise PriorityError(f'priority="{text}" must be fifo, rr or nice, optionally with a '
                            f'level (fifo:80, nice:-5), or off')
    if not level_text:
        return name, DEFAULT_NICE if name == "nice" else DEFAULT_RT_PRIORITY
    try:
        level = int(level_text)
    except ValueError:
        level = None
    low, high = (-20, 19) if name == "nice" else (1, 99)
    if level is None or not low <= level <= high:
        raise PriorityError(f'priority="{text}": the level of {name} must be a whole number '
                            f'from {low} to {high}')
    return name, level


def _parse_cpus(text: str | None) -> tuple[int, ...] | None:
    """Cores as Linux writes them: ``1``, ``0,2``, ``2-3``."""
    text = (text or "").strip()
    if not text:
        return None
    cores: set[int] = set()
    try:
        for part in text.split(","):
            first, _, last = part.strip().partition("-")
            cores.update(range(int(first), int(last or first) + 1))
    except ValueError:
        raise PriorityError(f'cpus="{text}" must list cores: 1, 0,2 or 2-3') from None
    allowed = os.sched_getaffinity(0)
    if not cores or not cores <= allowed:
        raise PriorityError(f'cpus="{text}": this process may use the cores '
                            f'{_core_list(allowed)} only')
    return tuple(sorted(cores))


def _core_list(cores) -> str:
    return ",".join(str(c) for c in sorted(cores))


@dataclass
class _State:
    request: PriorityRequest | None = None
    tick: str | None = None                 # what the tick thread was given
    memory_locked: bool | None = None
    refused: list[str] = field(default_factory=list)
    devices: dict = field(default_factory=dict)       # thread -> what it was given
    background: dict = field(default_factory=dict)    # thread -> what it was given
    pending: list = field(default_factory=list)       # (thread, table, give) until a request


_state = _State()
_lock = threading.Lock()


def configure(request: PriorityRequest | None) -> None:
    """Set the process's request (None: nothing asked; what was set before stays). Threads
    registered earlier get their priority now."""
    if request is None:
        return
    with _lock:
        if request == _state.request:
            return
        _state.request = request
        _state.tick = None
        _state.refused.clear()
        if request.lock_memory and _state.memory_locked is None:
            _state.memory_locked = _lock_memory()
        for thread, table, give in _state.pending:
            getattr(_state, table)[thread] = give(thread.native_id, request)


def tick_thread() -> dict | None:
    """Give the calling thread (the one running ticks) the requested priority and cores;
    returns :func:`report`, or None when nothing was asked for."""
    with _lock:
        request = _state.request
        if request is None:
            return None
        _state.tick = _apply_rt(threading.get_native_id(), request, "tick thread")
    return report()


def device_thread() -> None:
    """Call first thing in a thread that talks to a device: it runs as the tick thread does."""
    _register("devices", _as_device)


def background_thread() -> None:
    """Call first thing in a thread of ikaros that must not take the tick's time (the
    recorder's writer): when a priority is asked for, it runs below the tick."""
    _register("background", _as_background)


def below_tick_thread() -> None:
    """Call first thing in a thread of ikaros that runs Python code often while the ticks
    run and must not take their time (the web UI's server and image encoder): when the tick
    asks for a real-time policy, it runs under that policy ``BELOW_TICK`` levels lower, so
    the tick preempts it and the other processes of the machine do not (preempted while it
    holds Python's lock, it would keep the tick waiting for the lock); under any other
    request it runs as a :func:`background_thread`. It is listed with those."""
    _register("background", _below_tick)


def _register(table: str, give) -> None:
    """Give the calling thread ``give(native id, request)`` now, or when the request comes
    (:func:`configure`), and keep what it runs at in ``_state.<table>``."""
    thread = threading.current_thread()
    with _lock:
        _forget_dead()
        if _state.request is None:
            _state.pending.append((thread, table, give))
        else:
            getattr(_state, table)[thread] = give(thread.native_id, _state.request)


def report() -> dict | None:
    """What was asked for, granted and refused (None when nothing was asked for)."""
    with _lock:
        request = _state.request
        if request is None:
            return None
        _forget_dead()
        return {
            "requested": str(request),
            "tick_thread": _state.tick,
            "device_threads": sorted({str(v) for v in _state.devices.values()}),
            "background_threads": sorted({str(v) for v in _state.background.values()}),
            "cpus": list(request.cpus) if request.cpus is not None else None,
            "memory_locked": _state.memory_locked,
            "refused": list(_state.refused),
        }


def reset() -> None:
    """Forget the request (tests; the threads keep what they were given)."""
    global _state
    with _lock:
        _state = _State()


def _forget_dead() -> None:
    for table in (_state.devices, _state.background):
        for thread in [t for t in table if not t.is_alive()]:
            del table[thread]
    _state.pending[:] = [entry for entry in _state.pending if entry[0].is_alive()]


def _refuse(message: str) -> None:
    if message not in _state.refused:
        _state.refused.append(message)


def _apply_rt(tid: int, request: PriorityRequest, who: str) -> str:
    """Give thread ``tid`` the request's policy and cores; returns what it runs at."""
    if request.cpus is not None:
        try:
            os.sched_setaffinity(tid, request.cpus)
        except OSError as error:
            _refuse(f"pinning the {who} to cores {_core_list(request.cpus)}: "
                    f"{error.strerror}")
    if request.policy in POLICIES:
        name = POLICIES[request.policy]
        try:
            os.sched_setscheduler(tid, getattr(os, name), os.sched_param(request.level))
            return f"{name} {request.level}"
        except PermissionError as error:
            _refuse(f"{name} {request.level} for the {who}: {error.strerror}; "
                    + _RTPRIO_HELP.format(python=os.path.realpath(sys.executable)))
        return _best_nice(tid, DEFAULT_NICE, who)
    if request.policy == "nice":
        return _best_nice(tid, request.level, who)
    return f"nice {os.getpriority(os.PRIO_PROCESS, tid)}"


def _best_nice(tid: int, wanted: int, who: str) -> str:
    """The nice closest to ``wanted`` that this process may take (Linux: 20 - RLIMIT_NICE
    without CAP_SYS_NICE), never above the thread's own."""
    current = os.getpriority(os.PRIO_PROCESS, tid)
    try:
        os.setpriority(os.PRIO_PROCESS, tid, wanted)
        return f"nice {wanted}"
    except PermissionError:
        pass
    floor = 20 - resource.getrlimit(resource.RLIMIT_NICE)[0]
    best = max(wanted, floor)
    if best < current:
        try:
            os.setpriority(os.PRIO_PROCESS, tid, best)
        except PermissionError:
            best = current
    _refuse(f"nice {wanted} for the {who}: not permitted (it runs at nice "
            f"{min(best, current)}); " + _NICE_HELP)
    return f"nice {min(best, current)}"


def _as_device(tid: int, request: PriorityRequest) -> str:
    return _apply_rt(tid, request, "device thread")


def _as_background(tid: int, request: PriorityRequest) -> str:
    return _lower(tid)


def _lower(tid: int) -> str:
    """Run thread ``tid`` under the normal policy at ``BACKGROUND_NICE`` (always allowed)."""
    try:
        os.sched_setscheduler(tid, os.SCHED_OTHER, os.sched_param(0))
        nice = max(os.getpriority(os.PRIO_PROCESS, tid), BACKGROUND_NICE)
        os.setpriority(os.PRIO_PROCESS, tid, nice)
        return f"nice {nice}"
    except OSError as error:        # the thread ended meanwhile
        return f"unchanged ({error.strerror})"


def _below_tick(tid: int, request: PriorityRequest) -> str:
    """Run thread ``tid`` under the request's real-time policy ``BELOW_TICK`` levels below
    the tick (level 1 at least; the threads it starts do not inherit the policy); as
    :func:`_lower` when the request is not real-time, the tick is at level 1 already, or the
    policy is not permitted (the tick's own refusal says so)."""
    if request.policy in POLICIES and request.level > 1:
        name = POLICIES[request.policy]
        level = max(1, request.level - BELOW_TICK)
        try:
            os.sched_setscheduler(tid, getattr(os, name) | os.SCHED_RESET_ON_FORK,
                                  os.sched_param(level))
            return f"{name} {level}"
        except PermissionError:
            pass
        except OSError as error:        # the thread ended meanwhile
            return f"unchanged ({error.strerror})"
    return _lower(tid)


MCL_CURRENT, MCL_FUTURE = 1, 2


def _lock_memory() -> bool:
    """Lock the process's memory (``mlockall``) where that cannot later make allocations
    fail: as root or with no limit on locked memory."""
    soft, _ = resource.getrlimit(resource.RLIMIT_MEMLOCK)
    if os.geteuid() != 0 and soft != resource.RLIM_INFINITY:
        _refuse(f"locking memory: the limit is {soft // 1024} KiB; " + _MEMLOCK_HELP)
        return False
    libc = ctypes.CDLL(ctypes.util.find_library("c"), use_errno=True)
    if libc.mlockall(MCL_CURRENT | MCL_FUTURE) != 0:
        _refuse(f"locking memory: {os.strerror(ctypes.get_errno())}; " + _MEMLOCK_HELP)
        return False
    return True
