"""Ctrl-C (SIGINT) for the ``ikaros`` command: it always ends the process within seconds.

``install()`` makes SIGINT raise ``Interrupted`` in the main thread and arms a watchdog:
if the process has not ended ``GRACE`` seconds later (a module that loops in ``init`` and
swallows the interrupt, a build stuck in a worker thread), it exits at once with status 130.
While the handler is installed, a ``KeyboardInterrupt`` (or ``SystemExit``) that a module
raises itself is that module's error, told apart from a real Ctrl-C.
"""
from __future__ import annotations

import os
import signal
import sys
import threading

GRACE = 2.0            # seconds from Ctrl-C to a forced exit
EXIT_INTERRUPTED = 130  # 128 + SIGINT, as shells report it

_installed = False


class Interrupted(KeyboardInterrupt):
    """Ctrl-C, received while ikaros's handler is installed."""


def install(grace: float = GRACE) -> None:
    """Make SIGINT raise Interrupted and end the process within ``grace`` seconds. SIGTERM
    (kill, a closing session) ends a run the same way, so every module's stop() runs and
    devices reach their safe state before the process exits. A process started with
    SIGINT ignored (a split model's worker, ``nohup``) keeps ignoring it."""
    global _installed

    def handler(signum, frame):
        if _watchdog.is_set():
            force_exit()                 # a second Ctrl-C: at once
        _arm(grace)
        raise Interrupted()

    if signal.getsignal(signal.SIGINT) is not signal.SIG_IGN:    # (ignored: left so)
        signal.signal(signal.SIGINT, handler)
    signal.signal(signal.SIGTERM, handler)
    _installed = True


def module_faults() -> tuple:
    """The exceptions a module call is blamed for: every Exception, ``SystemExit``, and
    ``KeyboardInterrupt`` when a real Ctrl-C raises ``Interrupted`` instead."""
    if _installed:
        return (Exception, SystemExit, KeyboardInterrupt)
    return (Exception, SystemExit)


def is_interrupt(error: BaseException) -> bool:
    """Whether an exception caught around a module call is a real Ctrl-C (to re-raise)."""
    return isinstance(error, Interrupted) or \
        (isinstance(error, KeyboardInterrupt) and not _installed)


_watchdog = threading.Event()


def _arm(grace: float) -> None:
    if _watchdog.is_set():
        return
    _watchdog.set()
    timer = threading.Timer(grace, _give_up, (grace,))
    timer.daemon = True
    timer.start()


def _give_up(grace: float) -> None:
    print(f"ikaros: interrupted; forced to exit (not done {grace:g} s after Ctrl-C)\n",
          end="", file=sys.stderr)        # one write: the main thread may be printing
    force_exit()


def force_exit(status: int = EXIT_INTERRUPTED) -> None:
    """End the process now, without waiting for threads that never end."""
    try:
        sys.stdout.flush()
        sys.stderr.flush()
    finally:
        os._exit(status)


def fault_text(error: BaseException) -> str:
    """What a module's exception was, for its error message."""
    if isinstance(error, SystemExit):
        return f"the module called sys.exit({'' if error.code is None else repr(error.code)})"
    if isinstance(error, KeyboardInterrupt):
        return "the module raised KeyboardInterrupt"
    text = str(error)
    return f"{type(error).__name__}: {text}" if text else type(error).__name__
