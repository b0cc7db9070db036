"""Whole link messages while Ctrl-C or SIGTERM may come: a message of several ZeroMQ frames
is sent and received a frame at a time, so a KeyboardInterrupt raised between two frames
would leave half a message in the socket (the next read takes its rest as a message, and
the link reports a message it cannot read). ``signals_held`` holds those signals back for
the few microseconds of one message and hands them on after it."""
from __future__ import annotations

import contextlib
import signal
import threading

HELD = (signal.SIGINT, signal.SIGTERM)


@contextlib.contextmanager
def signals_held():
    """Within it, SIGINT and SIGTERM are kept and delivered when it ends (only Python's
    main thread receives them; elsewhere this does nothing)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    came: list = []
    saved = {s: signal.getsignal(s) for s in HELD}
    for s, handler in saved.items():
        if handler not in (signal.SIG_IGN, None):
            signal.signal(s, lambda signum, frame: came.append((signum, frame)))
    try:
        yield
    finally:
        for s, handler in saved.items():
            if handler not in (signal.SIG_IGN, None):
                signal.signal(s, handler)
        for signum, frame in came:
            handler = saved[signum]
            if callable(handler):
                handler(signum, frame)
            else:               # the default action, now that it is restored
                signal.raise_signal(signum)
