"""Whole link messages while Ctrl-C or SIGTERM may come: a message of several ZeroMQ frames
is sent and received a frame at a time, so a KeyboardInterrupt raised between two frames
would leave half a message in the socket (the next read takes its rest as a message, and
the link reports a message it cannot read).

A ``SignalHold`` installed in the main thread puts a handler of its own before the
process's SIGINT and SIGTERM handlers; inside ``with hold:`` (one message) the signals are
kept, and handed to those handlers when it ends; outside, at once. Entering and leaving
costs two attribute writes, not two handler swaps (``signal.signal`` takes about 8 us)."""
from __future__ import annotations

import signal
import threading

HELD = (signal.SIGINT, signal.SIGTERM)


class SignalHold:
    """Holds SIGINT and SIGTERM back inside ``with`` once ``install()``-ed (in the main
    thread: only it receives them; elsewhere it holds nothing)."""

    def __init__(self):
        self._holding = False
        self._came: list = []
        self._saved: dict = {}          # signal -> the handler it had

    def install(self) -> None:
        if threading.current_thread() is not threading.main_thread() or self._saved:
            return
        for s in HELD:
            handler = signal.getsignal(s)
            if handler not in (signal.SIG_IGN, None):
                self._saved[s] = handler
                signal.signal(s, self._handler)

    def uninstall(self) -> None:
        """Give the handlers back (those nobody replaced meanwhile)."""
        for s, handler in self._saved.items():
            if signal.getsignal(s) == self._handler:
                signal.signal(s, handler)
        self._saved = {}

    def _handler(self, signum, frame) -> None:
        if self._holding:
            self._came.append((signum, frame))
        else:
            self._deliver(signum, frame)

    def _deliver(self, signum, frame) -> None:
        handler = self._saved.get(signum, signal.SIG_DFL)
        if callable(handler):
            handler(signum, frame)
        else:                   # the default action
            self.uninstall()
            signal.signal(signum, signal.SIG_DFL)
            signal.raise_signal(signum)

    def __enter__(self) -> "SignalHold":
        self._holding = True
        return self

    def __exit__(self, *exc) -> None:
        self._holding = False
        if self._came:
            came, self._came = self._came, []
            for signum, frame in came:
                self._deliver(signum, frame)
