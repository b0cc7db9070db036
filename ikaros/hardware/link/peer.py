"""The two ends of a data link: a Publisher that binds and sends every tick, and a
Subscriber that connects, reports a lost peer and reconnects by itself (ZeroMQ PUB/SUB)."""
from __future__ import annotations

import errno
import math
import time

from ...module import require
from .endpoint import check_key, tcp
from .wire import BadMessage, LinkError, WrongKey, decode, encode

HEARTBEAT_MS = 500          # a silent TCP peer is declared lost after HEARTBEAT_TIMEOUT_MS
HEARTBEAT_TIMEOUT_MS = 2000
RECONNECT_MS = 100
BIND_WAIT = 1.0             # seconds a port still held by a socket just closed is waited for


def zmq_module():
    """pyzmq, or a MissingDependency naming the pip install that fixes it."""
    return require("zmq", "pyzmq", extra="links")


class Publisher:
    """Binds ``host:port`` and publishes signed messages to every subscriber."""

    def __init__(self, host: str, port: int, key: bytes | None, queue: int = 64):
        zmq = zmq_module()
        check_key(host, key, "the address to bind")
        self.key = key
        self.socket = zmq.Context.instance().socket(zmq.PUB)
        self.socket.setsockopt(zmq.LINGER, 0)
        self.socket.setsockopt(zmq.SNDHWM, queue)
        # ZeroMQ lets go of a closed socket's port in its own thread, a moment later: a
        # model loaded again right after the last one closed waits for it, up to BIND_WAIT
        deadline = time.monotonic() + BIND_WAIT
        while True:
            try:
                if port == 0:
                    port = self.socket.bind_to_random_port(tcp(host, 0).rpartition(":")[0])
                else:
                    self.socket.bind(tcp(host, port))
                break
            except zmq.ZMQError as e:
                if e.errno == errno.EADDRINUSE and time.monotonic() < deadline:
                    time.sleep(0.02)
                    continue
                self.socket.close()
                raise LinkError(f"cannot bind {tcp(host, port)}: {e}") from None
        self.port = port

    def send(self, header: dict, arrays=()) -> None:
        self.socket.send_multipart(encode(header, arrays, self.key), copy=False)

    def close(self) -> None:
        self.socket.close(0)


class Subscriber:
    """Connects to a Publisher. ``receive`` returns the next message (or the newest one),
    waiting up to a time-out; ``events`` says when the peer was lost or came back."""

    def __init__(self, host: str, port: int, key: bytes | None, queue: int = 1000):
        zmq = self.zmq = zmq_module()
        check_key(host, key, "the server address")
        self.key = key
        self.address = tcp(host, port)
        s = self.socket = zmq.Context.instance().socket(zmq.SUB)
        s.setsockopt(zmq.LINGER, 0)
        s.setsockopt(zmq.RCVHWM, queue)
        s.setsockopt(zmq.RECONNECT_IVL, RECONNECT_MS)
        s.setsockopt(zmq.HEARTBEAT_IVL, HEARTBEAT_MS)
        s.setsockopt(zmq.HEARTBEAT_TIMEOUT, HEARTBEAT_TIMEOUT_MS)
        s.setsockopt(zmq.SUBSCRIBE, b"")
        self.monitor = s.get_monitor_socket(zmq.EVENT_CONNECTED | zmq.EVENT_DISCONNECTED)
        try:
            s.connect(self.address)
        except zmq.ZMQError as e:
            self.close()
            raise LinkError(f"cannot connect to {self.address}: {e}") from None
        self.poller = zmq.Poller()
        self.poller.register(s, zmq.POLLIN)
        self.connected = False

    def events(self) -> list[str]:
        """"connected" / "disconnected" events since the last call (the connection state
        is in ``connected``)."""
        from zmq.utils.monitor import recv_monitor_message
        zmq, found = self.zmq, []
        while self.monitor.poll(0):
            event = recv_monitor_message(self.monitor)["event"]
            if event == zmq.EVENT_CONNECTED:
                self.connected = True
                found.append("connected")
            elif event == zmq.EVENT_DISCONNECTED:
                self.connected = False
                found.append("disconnected")
        return found

    def receive(self, timeout: float, newest: bool = False):
        """The next message as (header, arrays), or the newest waiting one with
        ``newest``; None when none came within ``timeout`` seconds. A message that fails
        its signature raises WrongKey, one that is not a link message BadMessage (both
        after the message has been taken off the queue)."""
        zmq = self.zmq
        deadline = time.perf_counter() + timeout
        frames = None
        while True:
            try:
                frames = self.socket.recv_multipart(zmq.NOBLOCK)
                if not newest:
                    break
                continue
            except zmq.Again:
                if frames is not None:
                    break
            left = deadline - time.perf_counter()
            if left <= 0:
                return None
            self.poller.poll(math.ceil(left * 1000))
        return decode(frames, self.key)

    def close(self) -> None:
        self.socket.disable_monitor()
        self.monitor.close(0)
        self.socket.close(0)


__all__ = ["Publisher", "Subscriber", "LinkError", "WrongKey", "BadMessage"]
