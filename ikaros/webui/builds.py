"""Builds started from the web UI run in a thread of their own, with a time limit.

A build that does not finish in time (a module that loops in ``init``) is answered with an
error and left behind: a Python thread cannot be stopped, so it runs on as a daemon thread,
and whatever it builds when (if ever) it ends is closed at once. Later builds are not held
up by it, and the process can still exit (``stuck()`` tells the command to leave without
waiting for it).
"""
from __future__ import annotations

import asyncio
import threading

DEFAULT_BUILD_TIMEOUT = 30.0    # seconds

_stuck: set[threading.Thread] = set()
_lock = threading.Lock()


class BuildTimeout(Exception):
    """A build did not finish within its time limit."""


def stuck() -> int:
    """How many builds that timed out are still running."""
    with _lock:
        return sum(1 for t in _stuck if t.is_alive())


async def run_build(fn, timeout: float):
    """Run ``fn()`` (which returns a network) in a new daemon thread; its result, or its
    exception. BuildTimeout after ``timeout`` seconds; a network built after that is
    closed."""
    loop = asyncio.get_running_loop()
    future = loop.create_future()
    state = {"abandoned": False}
    state_lock = threading.Lock()

    def settle(setter, value):
        if not future.done():
            setter(value)

    def work():
        try:
            result = fn()
        except BaseException as e:          # noqa: BLE001 - handed to the awaiting request
            with state_lock:
                if not state["abandoned"]:
                    loop.call_soon_threadsafe(settle, future.set_exception, e)
        else:
            with state_lock:
                abandoned = state["abandoned"]
                if not abandoned:
                    loop.call_soon_threadsafe(settle, future.set_result, result)
            if abandoned:
                _discard(result)
        finally:
            with _lock:
                _stuck.discard(threading.current_thread())

    thread = threading.Thread(target=work, name="ikaros-build", daemon=True)
    thread.start()
    try:
        return await asyncio.wait_for(asyncio.shield(future), timeout)
    except asyncio.TimeoutError:
        with state_lock:
            state["abandoned"] = True
        # a result already on its way to the future is closed when it arrives
        future.add_done_callback(_discard_result)
        with _lock:
            if thread.is_alive():
                _stuck.add(thread)
        raise BuildTimeout(f"the build did not finish within {timeout:g} s (does a "
                           f"module's init or configure never return?); it was abandoned")


def _discard_result(future) -> None:
    if not future.cancelled() and future.exception() is None:
        _discard(future.result())


def _discard(net) -> None:
    close = getattr(net, "close", None)
    if close is not None:
        try:
            close()
        except Exception:                  # noqa: BLE001 - a network nobody will use
            pass
