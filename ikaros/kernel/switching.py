"""A short GIL switch interval while a helper thread works beside the kernel.

A thread that runs Python (or NumPy, or numba code that keeps the GIL: the compiled tick)
gives the GIL up to a waiting thread only every ``sys.getswitchinterval()`` (5 ms by
default). A helper thread that needs the GIL now and then (the compiled plan made in the
background, a recording's writer between its GIL-free compressions) would wait that long
each time, and the kernel thread, when it is the one waiting (a real-time tick that wakes
up), too. While any helper works (``shorten()`` ... ``restore()``, counted), the interval is
at most ``SWITCH_INTERVAL``.
"""
from __future__ import annotations

import sys
import threading

SWITCH_INTERVAL = 0.0002      # seconds

_lock = threading.Lock()
_users = [0]                  # helpers at work (they share the interval)
_saved = [0.005]              # the interval before the first of them


def shorten() -> None:
    """A helper starts working."""
    with _lock:
        if _users[0] == 0:
            _saved[0] = sys.getswitchinterval()
            sys.setswitchinterval(min(_saved[0], SWITCH_INTERVAL))
        _users[0] += 1


def restore() -> None:
    """A helper has stopped working: the interval before the first one, once none works."""
    with _lock:
        _users[0] -= 1
        if _users[0] == 0:
            sys.setswitchinterval(_saved[0])
