"""Safe states of drivers: a watchdog for runs that stop ticking, and a last call at exit.

Every driver that can move something registers a ``safe_stop()`` callable with
:func:`on_exit` while its device is open; at interpreter exit (a script that never closed
its network, ``sys.exit``, an uncaught exception) every registered call runs once, in the
reverse order of registration. Drivers remove their entry when they close normally.

:class:`Watchdog` calls its action when nobody has called :meth:`Watchdog.kick` for
``timeout`` seconds: a driver kicks it every tick, so a run that is paused or hung in another
module brings its hardware to the safe state after ``timeout``.

:func:`shut_down` is the end of a driver's run, the same for every driver.
"""
from __future__ import annotations

import atexit
import logging
import threading
import time
from typing import Callable

from .. import priority

log = logging.getLogger(__name__)

_at_exit: dict[int, tuple[str, Callable[[], None]]] = {}
_lock = threading.Lock()
_counter = 0


def on_exit(what: str, safe_stop: Callable[[], None]) -> int:
    """Call ``safe_stop`` at interpreter exit unless :func:`cancel` is called first; returns a key."""
    global _counter
    with _lock:
        _counter += 1
        _at_exit[_counter] = (what, safe_stop)
        return _counter


def cancel(key: int | None) -> None:
    with _lock:
        _at_exit.pop(key, None)


@atexit.register
def _run_at_exit() -> None:
    with _lock:
        entries = sorted(_at_exit.items(), reverse=True)
        _at_exit.clear()
    for _, (what, safe_stop) in entries:
        try:
            safe_stop()
        except Exception as error:         # the others must still be made safe
            log.error("could not put %s in its safe state at exit: %s", what, error)


class Watchdog:
    """Calls ``action`` once when :meth:`kick` has not been called for ``timeout`` seconds."""

    def __init__(self, timeout: float, action: Callable[[], None], name: str = "watchdog"):
        self.timeout = float(timeout)
        self.action = action
        self.fired = False
        self._last = time.monotonic()
        self._stop = threading.Event()
        self._lock = threading.Lock()
        self._thread = threading.Thread(target=self._watch, name=name, daemon=True)
        if self.timeout > 0:
            self._thread.start()

    def kick(self) -> bool:
        """Note a tick; returns True when the watchdog had fired since the last kick."""
        with self._lock:
            self._last = time.monotonic()
            fired, self.fired = self.fired, False
        return fired

    def close(self) -> None:
        self._stop.set()
        if self._thread.is_alive() and self._thread is not threading.current_thread():
            self._thread.join(timeout=1.0)

    def _watch(self) -> None:
        priority.device_thread()
        while not self._stop.wait(min(0.05, self.timeout / 4)):
            with self._lock:
                due = not self.fired and time.monotonic() - self._last > self.timeout
                if due:
                    self.fired = True
            if due:
                try:
                    self.action()
                except Exception as error:
                    log.error("the watchdog could not reach the safe state: %s", error)


def shut_down(watchdog: Watchdog | None, make_safe: Callable[[], None], exit_key: int | None,
              device, simulator, report: Callable[[Exception], None]) -> None:
    """End a driver's run, every step tried: the watchdog ends, ``make_safe()`` puts an open
    ``device`` in its safe state (a DeviceError there goes to ``report``), the call at exit
    is cancelled, and the device (``close()``) and its simulator (``stop()``) are closed."""
    from . import DeviceError
    if watchdog is not None:
        watchdog.close()
    try:
        if device is not None:
            make_safe()
    except DeviceError as error:
        report(error)
    finally:
        cancel(exit_key)
        if device is not None:
            device.close()
        if simulator is not None:
            simulator.stop()
