"""The kernel's end of a worker process: starting it, requests over its pipe, and making
sure it ends."""
from __future__ import annotations

import atexit
import collections
import os
import signal
import subprocess
import threading
from typing import Callable

from .protocol import WorkerGone, receive, send

WORKER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "worker.py")
SHUTDOWN_TIMEOUT = 10.0     # seconds for the shutdown hook before the worker is killed
_live: set["WorkerProcess"] = set()


class WorkerCrashed(RuntimeError):
    """The worker process ended while the kernel waited for it."""

    def __init__(self, exit_code: int | None, stderr: list[str]):
        self.exit_code = exit_code
        self.stderr = stderr
        super().__init__(exit_text(exit_code))


def exit_text(code: int | None) -> str:
    """How a process ended: "ended with exit code 3", "was killed by signal 9 (SIGKILL)"."""
    if code is None:
        return "stopped answering"
    if code < 0:
        try:
            name = f" ({signal.Signals(-code).name})"
        except ValueError:
            name = ""
        return f"was killed by signal {-code}{name}"
    return f"ended with exit code {code}"


class WorkerProcess:
    """A worker running ``python worker.py``. Log messages that arrive while the kernel
    waits for an answer go to ``on_log(level, text)``; lines the process writes to its
    stderr go to ``on_stderr(line)`` once ``forward_stderr()`` is called (before, they are
    kept in ``stderr_lines`` for the error message of a worker that fails to start)."""

    def __init__(self, python: str, on_log: Callable[[str, str], None],
                 on_stderr: Callable[[str], None]):
        self.on_log, self.on_stderr = on_log, on_stderr
        self._forwarding = False
        self._stderr_lock = threading.Lock()
        self.stderr_lines: collections.deque = collections.deque(maxlen=40)
        self.proc = subprocess.Popen([python, WORKER], stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        _live.add(self)
        self._reader = threading.Thread(target=self._read_stderr, daemon=True,
                                        name=f"ikaros-script-stderr-{self.proc.pid}")
        self._reader.start()

    def _read_stderr(self) -> None:
        for raw in self.proc.stderr:
            line = raw.decode("utf-8", "replace").rstrip("\n")
            with self._stderr_lock:
                if not self._forwarding:
                    self.stderr_lines.append(line)
                    continue
            self.on_stderr(line)

    def forward_stderr(self) -> None:
        """From now on, and for the lines kept so far, call ``on_stderr``."""
        with self._stderr_lock:
            self._forwarding = True
            kept = list(self.stderr_lines)
            self.stderr_lines.clear()
        for line in kept:
            self.on_stderr(line)

    def request(self, kind: str, fields: dict | None = None,
                arrays: dict | None = None) -> tuple[dict, dict]:
        """Send a message and wait for the answer (log messages meanwhile go to
        ``on_log``). Raises WorkerCrashed if the worker ends first."""
        try:
            send(self.proc.stdin, kind, fields, arrays)
            return self._answer()
        except (WorkerGone, BrokenPipeError, ConnectionResetError):
            raise self._crashed() from None

    def _answer(self) -> tuple[dict, dict]:
        while True:
            header, arrays = receive(self.proc.stdout)
            if header["kind"] != "log":
                return header, arrays
            self.on_log(header["level"], header["text"])

    def _crashed(self) -> WorkerCrashed:
        try:
            code = self.proc.wait(timeout=SHUTDOWN_TIMEOUT)
        except subprocess.TimeoutExpired:
            code = None
        self.kill()
        self._reader.join(timeout=1.0)
        return WorkerCrashed(code, list(self.stderr_lines))

    def close(self) -> dict | None:
        """End the worker: closing its pipe makes it run the script's shutdown hook and
        exit; a worker that takes longer than SHUTDOWN_TIMEOUT is killed. Returns the
        shutdown's "failed" answer, if it failed. Answers to a request that was
        interrupted (Ctrl-C) are passed over; log messages are forwarded."""
        if self.proc.poll() is not None:
            self.kill()
            return None
        timer = threading.Timer(SHUTDOWN_TIMEOUT, self.kill)
        timer.daemon = True
        timer.start()
        failure = None
        try:
            self.proc.stdin.close()
            while True:
                header, _ = self._answer()
                if header["kind"] == "failed":
                    failure = header
        except (WorkerGone, OSError, ValueError):
            pass
        finally:
            try:
                self.proc.wait(timeout=SHUTDOWN_TIMEOUT)
            except subprocess.TimeoutExpired:
                pass
            timer.cancel()
            self.kill()
        return failure

    def kill(self) -> None:
        """Make sure the process has ended (killed if it still runs) and its pipes are
        closed."""
        if self.proc.poll() is None:
            self.proc.kill()
        try:
            self.proc.wait(timeout=SHUTDOWN_TIMEOUT)
        except subprocess.TimeoutExpired:
            pass
        for stream in (self.proc.stdin, self.proc.stdout):
            try:
                stream.close()
            except (OSError, ValueError):
                pass
        _live.discard(self)


@atexit.register
def _end_all() -> None:
    """No worker outlives the kernel's process, whatever way it ends."""
    for worker in list(_live):
        worker.close()
