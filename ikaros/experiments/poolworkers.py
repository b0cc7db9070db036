"""The life of a sweep's worker processes: they die with the sweep, every way it ends.

Each worker, when it starts (``start``), ignores Ctrl-C (the terminal sends it to the whole
process group; the sweep itself ends its workers) and asks Linux to send it SIGTERM when
its parent dies (``prctl(PR_SET_PDEATHSIG)``, so also when the sweep is killed with
SIGKILL); elsewhere a thread watches the parent. SIGTERM during a run interrupts the run
(its modules are stopped and its recording closed as not finished, and the run's row says
"interrupted" with the ticks it ran), and the worker exits at once if its parent is gone,
within ``CLOSE_GRACE`` seconds in any case. SIGTERM between runs exits when the parent is gone;
else the sweep, which sent it, ends the worker once the rows of the runs cut off are back
(an idle worker that exits at once would make the pool fail those runs' rows).

A run is interrupted once, and not once its ticks are done (``closing``): a SIGTERM that
comes while it stops its modules and closes its recording lets it finish (within
``CLOSE_GRACE``), as an exception raised there would cut off the closing and leave the
file marked open for writing. A dying sweep sends several: Linux sends the signal whenever
the *thread* that is the worker's parent exits, and hands the worker on to another thread
of the parent while it has one, so the sweep's threads, exiting one after another (tens of
milliseconds apart on a busy machine), each send one.
"""
from __future__ import annotations

import ctypes
import ctypes.util
import os
import signal
import sys
import threading
import time

from ..interrupt import Interrupted

PR_SET_PDEATHSIG = 1            # linux/prctl.h
EXIT_TERMINATED = 128 + signal.SIGTERM
WATCH_SECONDS = 0.2             # how often the watching thread looks for the parent
# how long an interrupted run may take to stop its modules and close its recording before
# the worker exits anyway: longer than Ctrl-C's 2 s, as on a busy machine closing can take
# that long, and a worker ended while it closes leaves its file marked open for writing
CLOSE_GRACE = 8.0

_state = {"parent": None, "running": False, "closing": False, "timer": None,
          "counters": None}


def start(parent: int, counters=None) -> None:
    """The initializer of a worker process of the sweep whose process id is ``parent``;
    its runs write the ticks they have done into ``counters`` (sweepprogress.TickCounters)
    when given."""
    _state["parent"] = parent
    _state["counters"] = counters
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, _terminated)
    if not _die_with_parent():
        threading.Thread(target=_watch_parent, name="ikaros-sweep-parent",
                         daemon=True).start()
    if os.getppid() != parent:          # it died before the request took hold
        _exit()


def run(function, spec):
    """``function(spec, report)`` in a worker, ``report`` recording the ticks done by the
    run (or None); after a run cut off by SIGTERM whose sweep is gone, the worker exits."""
    _state["running"] = True
    _state["closing"] = False
    _state["timer"] = None
    counters = _state["counters"]
    try:
        return function(spec, counters.reporter(spec.index) if counters is not None else None)
    finally:
        _state["running"] = False
        if os.getppid() != _state["parent"]:
            _exit()


def closing() -> None:
    """Tell the worker that its run's ticks are done (or cut off): a SIGTERM from now on
    lets the run end (see the module's docstring). Outside a worker it does nothing."""
    _state["closing"] = True


def _die_with_parent() -> bool:
    """Ask the kernel for SIGTERM when the parent dies; whether it took."""
    if not sys.platform.startswith("linux"):
        return False
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
        return libc.prctl(PR_SET_PDEATHSIG, int(signal.SIGTERM), 0, 0, 0) == 0
    except (OSError, AttributeError):
        return False


def _watch_parent() -> None:
    while os.getppid() == _state["parent"]:
        time.sleep(WATCH_SECONDS)
    os.kill(os.getpid(), signal.SIGTERM)


def _terminated(signum, frame) -> None:
    if not _state["running"]:
        if os.getppid() != _state["parent"]:
            _exit()
        return          # the sweep ends this idle worker itself, once the runs are back
    if _state["timer"] is None:
        _state["timer"] = threading.Timer(CLOSE_GRACE, _exit)
        _state["timer"].daemon = True
        _state["timer"].start()
    if not _state["closing"]:
        _state["closing"] = True
        raise Interrupted()


def _exit() -> None:
    try:
        sys.stderr.flush()
    finally:
        os._exit(EXIT_TERMINATED)
