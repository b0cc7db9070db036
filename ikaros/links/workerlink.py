"""The main process's end of the link to a worker that runs one process group of a split
model (split.py): starting a worker on this machine, the messages of a tick, finding a
worker lost (its process ended, the connection closed, or silent for ``stall_ticks`` tick
durations), and ending it."""
from __future__ import annotations

import os
import secrets
import selectors
import signal
import subprocess
import sys
import time

from ..kernel.scope import VariableError, substitute
from ..kernel.tree import Group
from .atomic import SignalHold
from ..hardware.link.endpoint import KEY_VARIABLE, check_key, link_key, split_address, tcp
from ..hardware.link.peer import zmq_module
from ..hardware.link.wire import LinkError, decode, encode

WORKER_PORT = 9200          # the default port of ``ikaros worker``
START_SECONDS = 60.0        # for a worker to start, build the model and initialise
POLL_SECONDS = 0.5          # how often a wait checks that the peer is still there
STALL_TICKS = 50            # a worker silent this many tick durations is lost (stall_ticks)
MIN_STALL_SECONDS = 0.2     # but never less (a loaded machine's scheduling)
END_SECONDS = 1.5           # for a lost worker's process to end after SIGTERM (then SIGKILL)
STOP_SECONDS = 2.0          # for a worker to acknowledge the end of its session


def stall_seconds(group: Group, tick_duration: float) -> float:
    """How long a worker may be silent (not even answering the link's heartbeats) before
    it is lost: the group's ``stall_ticks`` (default STALL_TICKS) tick durations, at least
    MIN_STALL_SECONDS. A worker busy with a long tick still answers the heartbeats (ZeroMQ
    answers them on its own thread); a stopped or hung process, or a lost machine, does
    not."""
    try:
        text = substitute(group.attrs.get("stall_ticks") or "", group.parent).strip()
    except VariableError as e:
        raise group.node.error(f"stall_ticks: {e}") from None
    if not text:            # (also a variable left empty)
        ticks = STALL_TICKS
    else:
        if not text.isdigit() or int(text) < 1:
            raise group.node.error(f'stall_ticks "{text}" must be a whole number of ticks '
                                   f'>= 1')
        ticks = int(text)
    return max(ticks * tick_duration, MIN_STALL_SECONDS)


class WorkerLink:
    """The main process's end of the link to the worker that runs ``group``."""

    def __init__(self, group: Group, where: str, incoming: list, outgoing: list):
        self.group = group
        self.where = where
        self.incoming = incoming        # sources the worker reads: sent every tick
        self.outgoing = outgoing        # the worker's sources others read: received
        self.process = None
        self.socket = None
        self.monitor = None
        self.requests: list = []        # parameter changes and commands for the next tick
        self.watched: dict = {}         # path -> array of other buffers to bring over
        self._asked: list = []          # the watched paths asked for with the last tick
        self.lost = None                # why the link was lost
        self.pending: int | None = None     # the tick sent and not yet answered
        self.listening = False          # whether the worker started here listens
        self.serving = False            # whether it has built and initialised its group
        self.hold = SignalHold()        # the network's, which it installs
        self.stall_seconds = MIN_STALL_SECONDS     # set from the model's timing
        self.remote = "://" in where or ":" in where
        self.what = f'the worker of group "{group.path}" (process="{where}")'

    def start(self, request: dict) -> None:
        zmq = zmq_module()
        if self.remote:
            host, port = split_address(self.where, WORKER_PORT)
            self.key = link_key(self.group.attrs.get("key"))
            try:
                check_key(host, self.key, f"the worker address of group {self.group.path}")
            except LinkError as e:
                raise self.group.node.error(str(e)) from None
        else:
            self.key = secrets.token_hex(16).encode()
            host, port = "127.0.0.1", self._spawn()
        s = self.socket = zmq.Context.instance().socket(zmq.DEALER)
        s.setsockopt(zmq.LINGER, 0)
        # a stalled worker is found by its silence: a heartbeat every quarter of the stall
        # time, and the link lost when none is answered within the stall time
        s.setsockopt(zmq.HEARTBEAT_IVL, max(1, int(self.stall_seconds * 250)))
        s.setsockopt(zmq.HEARTBEAT_TIMEOUT, max(1, int(self.stall_seconds * 1000)))
        self.monitor = s.get_monitor_socket(zmq.EVENT_DISCONNECTED)
        s.connect(tcp(host, port))
        self.address = tcp(host, port)
        request = dict(request, group=self.group.path,
                       incoming=[b.path for b in self.incoming],
                       outgoing=[b.path for b in self.outgoing])
        s.send_multipart(encode(request, key=self.key))

    def _spawn(self) -> int:
        """Start ``ikaros worker`` on this machine for one session; returns its port."""
        package_root = os.path.dirname(os.path.dirname(os.path.dirname(
            os.path.abspath(__file__))))     # the folder that holds ikaros/
        env = dict(os.environ, **{KEY_VARIABLE: self.key.decode()})
        env["PYTHONPATH"] = os.pathsep.join(
            p for p in (package_root, os.environ.get("PYTHONPATH")) if p)
        self.process = subprocess.Popen(
            [sys.executable, "-m", "ikaros", "worker", "--port", "0", "--once",
             "--parent", str(os.getpid())], stdout=subprocess.PIPE, env=env,
            preexec_fn=_ignore_ctrl_c)
        line = b""
        with selectors.DefaultSelector() as sel:
            sel.register(self.process.stdout, selectors.EVENT_READ)
            deadline = time.monotonic() + START_SECONDS
            while b"\n" not in line and time.monotonic() < deadline:
                if sel.select(POLL_SECONDS):
                    data = os.read(self.process.stdout.fileno(), 256)     # unbuffered
                    if not data:
                        break
                    line += data
        self.process.stdout.close()
        text = line.decode(errors="replace").partition("\n")[0].strip()
        if not text.startswith("ikaros worker: listening on tcp://"):
            self.process.kill()
            self.process.wait()
            raise self.group.node.error(f"{self.what} did not start: "
                                        f"{text or 'no answer'}")
        self.listening = True
        return int(text.rsplit(":", 1)[1].split()[0])

    def _receive(self, deadline: float | None = None, then=None):
        """The next message from the worker as (header, arrays), or what ``then(header,
        arrays)`` makes of it: a Ctrl-C or SIGTERM that comes while the message is read and
        taken waits until it is (the wait for it may be interrupted). LinkError when the
        worker is lost or refuses."""
        while True:
            self._wait(deadline)
            with self.hold:
                message = self._read()
                if message is not None:
                    return then(*message) if then is not None else message

    def _wait(self, deadline: float | None) -> None:
        """Until a message is there; LinkError when the worker is lost."""
        if self.lost:
            raise LinkError(self.lost)
        poll_ms = min(POLL_SECONDS, self.stall_seconds / 4) * 1000
        while not self.socket.poll(poll_ms):
            reason = None
            if self.process is not None and self.process.poll() is not None:
                reason = f"its process ended (exit status {self.process.returncode})"
            elif self.monitor.poll(0):
                reason = f"the connection was lost (silent for {self.stall_seconds:g} s, " \
                         f"or closed)"
            elif deadline is not None and time.monotonic() > deadline:
                reason = f"no answer within {START_SECONDS:g} s"
            if reason:
                self.lost = f"{self.what} at {self.address} was lost: {reason}"
                raise LinkError(self.lost)

    def _read(self) -> tuple[dict, list] | None:
        """The message that is there (None for the worker's check of the link)."""
        frames = self.socket.recv_multipart(zmq_module().NOBLOCK)
        try:
            header, arrays = decode(frames, self.key)
        except LinkError:
            header, arrays = decode(frames, None)       # only a refusal comes unsigned
            if header.get("type") != "refused":
                raise
        if header.get("type") == "ping":                # the worker checks the link
            return None
        if header.get("type") in ("refused", "error"):
            self.lost = f"{self.what} at {self.address}: {header.get('message')}"
            raise LinkError(self.lost)
        return header, arrays

    def ready(self) -> list:
        """Wait for the worker to have built and initialised its group; take its values
        of tick -1. Returns its notifications (level, module path, message)."""
        try:
            header, arrays = self._receive(time.monotonic() + START_SECONDS)
        except LinkError as e:
            raise self.group.node.error(str(e)) from None
        self._take(header, arrays, -1)
        self.serving = True
        return header.get("log", [])

    def send_tick(self, tick: int) -> None:
        if not self.lost:
            asked = list(self.watched)
            header = {"type": "tick", "tick": tick, "requests": self.requests,
                      "watch": asked}
            frames = encode(header, [b.array for b in self.incoming], self.key)
            with self.hold:        # sent whole, and then awaited
                self.socket.send_multipart(frames)
                self._asked, self.pending, self.requests = asked, tick, []

    def receive_tick(self) -> list:
        """Take the worker's values of the tick sent last; returns its notifications of
        the tick (an end of file or a fatal error among them ends the run here too)."""
        tick = self.pending

        def take(header, arrays):
            self.pending = None
            self._take(header, arrays, tick)
            return header.get("log", [])
        try:
            return self._receive(then=take)
        except LinkError:
            self.pending = None
            raise

    def _take(self, header, arrays, tick) -> None:
        asked = self._asked if tick >= 0 else []
        due = len(self.outgoing) + len(asked)
        if header.get("tick") != tick or len(arrays) != due:
            self.lost = (f"{self.what} sent tick {header.get('tick')} with {len(arrays)} "
                         f"arrays where tick {tick} with {due} was due")
            raise LinkError(self.lost)
        for buf, a in zip(self.outgoing, arrays):
            buf.array[...] = a.reshape(buf.shape)
        for path, a in zip(asked, arrays[len(self.outgoing):]):
            target = self.watched[path]
            target[...] = a.reshape(target.shape)

    def stop(self) -> None:
        """End the worker's session and close the link (once)."""
        if self.socket is not None:
            if not self.lost and not self._gone():
                with self.hold:
                    self.socket.send_multipart(encode({"type": "stop"}, key=self.key))
                if self.serving:                    # its acknowledgement, once stopped
                    deadline = time.monotonic() + STOP_SECONDS
                    while not self.socket.poll(POLL_SECONDS * 100) and not self._gone() \
                            and time.monotonic() < deadline:
                        pass
            self.socket.disable_monitor()
            self.monitor.close(0)
            self.socket.close(0)
            self.socket = None
        if self.process is not None:
            if (self.lost or not self.serving) and self.process.poll() is None:
                self._end_process()
            try:
                self.process.wait(10)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
            self.process = None

    def _gone(self) -> bool:
        """Whether the worker is known to be gone: its process here has ended, or the
        connection was lost (say it gave up on this process while it was stopped)."""
        return (self.process is not None and self.process.poll() is not None) or \
            bool(self.monitor.poll(0))

    def _end_process(self) -> None:
        """A worker started here that no longer answers (stopped, hung), or is still
        building the model: SIGTERM, so that its modules' stop() runs once it goes on
        (SIGCONT), and SIGKILL when it has not ended END_SECONDS later. One that has not
        yet said it listens (still starting Python) has nothing to stop: SIGKILL."""
        if not self.listening:
            self.process.kill()
            return
        self.process.terminate()
        if hasattr(signal, "SIGCONT"):
            self.process.send_signal(signal.SIGCONT)
        try:
            self.process.wait(END_SECONDS)
        except subprocess.TimeoutExpired:
            self.process.kill()


def _ignore_ctrl_c() -> None:
    """In a worker started here, before it runs: ignore SIGINT from its start on. A Ctrl-C
    reaches every process of the terminal's process group, and the main process stops its
    workers itself (a worker stopping on its own would answer a tick with its end)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
