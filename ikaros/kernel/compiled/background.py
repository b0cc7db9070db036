"""The compiled tick made in a background thread (``compiled="auto"``): the network starts
ticking on the NumPy plan at once; from its first tick a thread starts numba, loads the
compiled function from its cache and makes the compiled plan, and the network takes the plan
at the start of the next tick after it is ready (a tick boundary), so no tick mixes the two
and the results stay those of either plan, tick by tick. (The thread starts with the first
tick, not at the load, so that it competes with ticks and never with building a model.)

Starting numba costs about a second of Python imports and library loading. A thread that
runs Python gives the GIL up only every ``sys.getswitchinterval()`` (5 ms by default), which
would make a real-time tick that wakes up meanwhile wait that long; while the thread works,
the interval is short (``switching.py``), so a waking tick waits at most about that long."""
from __future__ import annotations

import threading

from .. import switching


class BackgroundPlan:
    """``make(cancelled)`` run in a daemon thread from ``start()``. ``ready`` once it has
    returned (its result in ``result``, None when it gave no plan or failed; ``error`` holds
    the failure). Modules whose parameters change meanwhile are noted in ``changed`` (the
    plan read them before).
    ``cancel()`` sets the Event ``make`` is given, so that it stops early."""

    def __init__(self, make):
        self._make = make
        self.result = None
        self.error: BaseException | None = None
        self.changed: set = set()
        self.done = threading.Event()
        self.cancelled = threading.Event()
        self.thread = threading.Thread(target=self._run, name="ikaros-compiled-plan",
                                       daemon=True)

    def start(self) -> None:
        switching.shorten()
        self.thread.start()

    @property
    def started(self) -> bool:
        return self.thread.ident is not None

    def _run(self) -> None:
        try:
            self.result = self._make(self.cancelled)
        except Exception as e:            # the NumPy plan goes on; the network reports it
            self.error = e
        finally:
            switching.restore()
            self.done.set()

    def cancel(self) -> None:
        """The plan is not needed any more (the network was closed)."""
        self.cancelled.set()

    @property
    def ready(self) -> bool:
        return self.done.is_set()

    def wait(self, timeout: float | None = None) -> bool:
        """Wait until the plan is made (or ``timeout`` seconds); whether it is."""
        return self.done.wait(timeout)
