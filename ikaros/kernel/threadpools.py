"""Numerical thread pools (BLAS, OpenMP, OpenCV) sized for real time.

A BLAS call that spreads over every core competes with the tick's own thread and with
everything else on the machine: on two shared cores a 1 ms tick of a population model then
varies from 0.25 to 12 ms. While a run is in real time the pools are limited to
``blas_threads`` threads (top-group setting, ``ikaros --blas-threads``; by default one
fewer than the cores the process may use, at least 1), through ``threadpoolctl``, and set
back when real time ends. OpenCV's own pool (its ``parallel_for``, which threadpoolctl does
not see) is sized alike through ``cv2.setNumThreads`` when a module has loaded OpenCV: with
1 its functions run in the calling thread, so a tick at a real-time priority (``priority``)
does not wait for OpenCV threads that run at the normal one.
"""
from __future__ import annotations

import os
import sys

try:
    import threadpoolctl
except ImportError:         # an optional extra: real time then leaves the pools alone
    threadpoolctl = None

INSTALL = "pip install threadpoolctl (or pip install 'ikaros[realtime]')"
UNLIMITED = ("off", "none", "no")


def default_threads() -> int:
    """One fewer than the cores this process may use (one is the tick's), at least 1."""
    return max(1, len(os.sched_getaffinity(0)) - 1)


def parse_setting(text: str | None) -> int | None:
    """``blas_threads``: a whole number >= 1, ``off`` (leave the pools alone; returned as
    0), or unset (None: the default)."""
    if text is None or text.strip() == "":
        return None
    stripped = text.strip().lower()
    if stripped in UNLIMITED:
        return 0
    if stripped.isdigit() and int(stripped) >= 1:
        if threadpoolctl is None:
            raise ValueError(f'blas_threads="{text}" needs the package threadpoolctl: '
                             f'{INSTALL}')
        return int(stripped)
    raise ValueError(f'blas_threads="{text}" must be a whole number >= 1, or off')


class ThreadPools:
    """Limits the pools while the run is in real time (``limit`` 0: never)."""

    def __init__(self, setting: int | None):
        self.limit = default_threads() if setting is None else setting
        self.active = False
        self._limiter = None
        self._opencv_threads: int | None = None     # OpenCV's before real time
        self._pools: list | None = None     # as last seen (threadpool_info is slow)

    def set_realtime(self, realtime: bool) -> None:
        """Called when the run enters (True) or leaves (False) real time."""
        if realtime == self.active:
            return
        self.active = realtime
        if self.limit == 0:
            return
        self._size_opencv(realtime)
        if threadpoolctl is None:
            return
        if realtime:
            self._limiter = threadpoolctl.threadpool_limits(limits=self.limit)
        elif self._limiter is not None:
            self._limiter.restore_original_limits()
            self._limiter = None
        self._pools = None

    def _size_opencv(self, realtime: bool) -> None:
        """OpenCV's threads: the limit in real time, what they were after it."""
        cv2 = _opencv()
        if cv2 is None:
            return
        if realtime:
            self._opencv_threads = cv2.getNumThreads()
            cv2.setNumThreads(self.limit)
        elif self._opencv_threads is not None:
            cv2.setNumThreads(self._opencv_threads)
            self._opencv_threads = None

    def report(self) -> dict:
        """The limit and, for each pool loaded, its library and threads now."""
        out: dict = {"limit": self.limit or None, "realtime": self.active}
        cv2 = _opencv()
        opencv = [] if cv2 is None else [{"api": "opencv", "library": "opencv",
                                          "threads": cv2.getNumThreads()}]
        if threadpoolctl is None:
            out["error"] = f"not limited: threadpoolctl is not installed ({INSTALL})"
            out["pools"] = opencv
            return out
        if self._pools is None:
            self._pools = [{"api": p.get("user_api"), "library": p.get("internal_api"),
                            "threads": p.get("num_threads")}
                           for p in threadpoolctl.threadpool_info()]
        out["pools"] = self._pools + opencv
        return out


def _opencv():
    """The cv2 module if a module has imported it (the kernel never imports OpenCV)."""
    cv2 = sys.modules.get("cv2")
    return cv2 if hasattr(cv2, "setNumThreads") else None
