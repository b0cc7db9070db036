"""``ikaros worker``: a kernel process that runs one group of a model for another kernel.

It listens on 127.0.0.1 by default; listening on an address other machines can reach needs
a shared key (``--key`` or IKAROS_LINK_KEY), and a request signed with another key is
refused. It serves one main process at a time, then waits for the next (``--once``: exits
after one session).
"""
from __future__ import annotations

import argparse
import os
import sys

from ..errors import ModelError, RunError
from ..hardware.link.endpoint import check_key, link_key, tcp
from ..hardware.link.peer import HEARTBEAT_MS, HEARTBEAT_TIMEOUT_MS, zmq_module
from ..hardware.link.wire import LinkError, decode, encode
from .split import worker_network
from .workerlink import POLL_SECONDS, WORKER_PORT


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="ikaros worker",
                                description="Run groups of models for other ikaros kernels "
                                            '(<group process="host:port">).')
    p.add_argument("--bind", default="127.0.0.1", metavar="ADDRESS",
                   help="address to listen on (default 127.0.0.1; any other needs a key)")
    p.add_argument("--port", type=int, default=WORKER_PORT,
                   help=f"port to listen on (default {WORKER_PORT}; 0 picks a free one)")
    p.add_argument("--key", help="the shared key (default: the environment variable "
                                 "IKAROS_LINK_KEY)")
    p.add_argument("--once", action="store_true", help="exit after one session")
    p.add_argument("--parent", type=int, help=argparse.SUPPRESS)   # exit when it is gone
    return p


def main(argv: list[str]) -> int:
    opts = parser().parse_args(argv)
    try:
        Worker(opts.bind, opts.port, link_key(opts.key), opts.parent).serve(opts.once)
    except LinkError as e:
        print(f"ikaros worker: error: {e}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        pass
    return 0


class Worker:
    def __init__(self, host: str, port: int, key: bytes | None, parent: int | None = None):
        zmq = self.zmq = zmq_module()
        check_key(host, key, "the address to listen on")
        self.key = key
        self.parent = parent
        s = self.socket = zmq.Context.instance().socket(zmq.ROUTER)
        s.setsockopt(zmq.LINGER, 0)
        s.setsockopt(zmq.ROUTER_MANDATORY, 1)
        s.setsockopt(zmq.HEARTBEAT_IVL, HEARTBEAT_MS)
        s.setsockopt(zmq.HEARTBEAT_TIMEOUT, HEARTBEAT_TIMEOUT_MS)
        self.monitor = s.get_monitor_socket(zmq.EVENT_DISCONNECTED)
        try:
            if port == 0:
                port = s.bind_to_random_port(tcp(host, 0).rpartition(":")[0])
            else:
                s.bind(tcp(host, port))
        except zmq.ZMQError as e:
            raise LinkError(f"cannot listen on {tcp(host, port)}: {e}") from None
        self.address = tcp(host, port)

    def serve(self, once: bool) -> None:
        print(f"ikaros worker: listening on {self.address}", flush=True)
        if self.parent is not None:          # spawned: the rest of stdout goes to stderr
            os.dup2(2, 1)
        try:
            while True:
                peer, header, arrays = self._next()
                if peer is None:
                    return
                if header.get("type") == "load":
                    self._session(peer, header)
                    if once:
                        return
                else:
                    self._answer(peer, {"type": "refused", "message": "no model loaded"})
        finally:
            self.monitor.close(0)
            self.socket.close(0)

    def _send(self, peer: bytes, header: dict, arrays=(), signed: bool = True) -> None:
        self.socket.send_multipart([peer] + encode(header, arrays,
                                                   self.key if signed else None))

    def _answer(self, peer: bytes, header: dict, arrays=(), signed: bool = True) -> bool:
        """Send to a peer; False when it is gone (a main process that found this worker
        silent too long, say after a SIGSTOP, and ended the run; its last messages may
        still come in after)."""
        try:
            self._send(peer, header, arrays, signed)
            return True
        except self.zmq.ZMQError:
            return False

    def _next(self, session: bytes | None = None):
        """(peer, header, arrays) of the next acceptable message; (None, None, None) when
        the session's peer (or the spawning process) is gone."""
        zmq = self.zmq
        while True:
            while not self.socket.poll(POLL_SECONDS * 1000):
                if self.parent is not None and os.getppid() != self.parent:
                    return None, None, None
                if session is not None and self._drain_monitor() and not self._alive(session):
                    return None, None, None
            peer, *frames = self.socket.recv_multipart(zmq.NOBLOCK)
            try:
                header, arrays = decode(frames, self.key)
            except LinkError as e:
                self._answer(peer, {"type": "refused", "message": f"refused: {e}"},
                             signed=False)
                print(f"ikaros worker: refused a request: {e}", file=sys.stderr, flush=True)
                continue
            if session is not None and peer != session:
                self._answer(peer, {"type": "refused", "message": "busy with another model"})
                continue
            return peer, header, arrays

    def _drain_monitor(self) -> bool:
        """Whether some peer has disconnected since the last call."""
        found = False
        while self.monitor.poll(0):
            self.monitor.recv_multipart()
            found = True
        return found

    def _alive(self, peer: bytes) -> bool:
        """Whether ``peer`` is still connected (a router cannot send to one that is gone)."""
        return self._answer(peer, {"type": "ping"})

    def _session(self, peer: bytes, request: dict) -> None:
        from ..kernel.builder import Builder
        from ..language.diagnostics import Diagnostics
        try:
            diagnostics = Diagnostics(strict=request.get("strict", False),
                                      lenient=request.get("lenient", False), quiet=True)
            net = Builder(request["filename"], request.get("overrides"),
                          text=request["text"], diagnostics=diagnostics,
                          network_factory=worker_network(request["group"],
                                                         request["incoming"],
                                                         request["outgoing"])).build()
        except (ModelError, RunError, LinkError, KeyError, OSError) as e:
            self._answer(peer, {"type": "error", "message": f"could not load the model: {e}"})
            return
        header: dict | None = {}
        self._drain_monitor()
        if self.parent is None:
            print(f"ikaros worker: running group {request['group']} of "
                  f"{request['filename']}", file=sys.stderr, flush=True)
        try:
            if not self._answer(peer, {"type": "ready", "tick": -1, "log": net.take_log()},
                                net.sources()):
                header = None
            while header is not None:
                _, header, arrays = self._next(peer)
                if header is None or header.get("type") == "stop":
                    break
                if not net.stopped:
                    net.apply(header.get("requests", []))
                    net.take(arrays)
                    try:
                        net.step()
                    except RunError:
                        pass            # the fatal error is in the log it sends
                if not self._answer(peer, {"type": "tick", "tick": header.get("tick"),
                                           "log": net.take_log()},
                                    net.sources(header.get("watch", []))):
                    header = None
        finally:
            net.close()
            if header is not None:
                self._answer(peer, {"type": "stopped"})
            elif self.parent is None:
                print("ikaros worker: the main process is gone; the session ended",
                      file=sys.stderr, flush=True)
