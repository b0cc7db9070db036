"""An Open Pixel Control server on 127.0.0.1 that keeps the pixels it is sent (a virtual
fcserver with one FadeCandy board): ``pixels[channel]`` is an (n, 3) uint8 array of the last
colours sent to that channel, ``messages`` every (channel, command, data) received, and
``board`` the (512, 3) colours of the board's eight outputs of 64 LEDs as fcserver's built-in
map drives them: OPC channel 0, pixels 0..511; messages to other channels light nothing. Faults: ``disconnect()`` drops every
connection and stops listening (a server that goes away); ``stall()`` keeps the connections
but reads nothing more (a server that hangs).
"""
from __future__ import annotations

import argparse
import select
import socket
import threading

import numpy as np

from ikaros.hardware.opc import SET_PIXELS, parse_messages

HELP = "an Open Pixel Control server for FadeCandy LED strips (on 127.0.0.1)"
BOARD_PIXELS = 512               # eight outputs of 64 pixels
MAPPED_CHANNEL = 0               # the only channel fcserver's default map takes

_POLL_SECONDS = 0.05


class VirtualOPCServer:
    name = "opc"

    def __init__(self, port: int = 0):
        self.port = port
        self.pixels: dict[int, np.ndarray] = {}
        self.board = np.zeros((BOARD_PIXELS, 3), np.uint8)
        self.messages: list[tuple[int, int, bytes]] = []
        self._listener: socket.socket | None = None
        self._clients: dict[socket.socket, bytearray] = {}
        self._thread: threading.Thread | None = None
        self._stopping = threading.Event()
        self._stalled = threading.Event()
        self._lock = threading.Lock()

    @property
    def path(self) -> str:
        """``127.0.0.1:PORT``, the address a client connects to."""
        return f"127.0.0.1:{self.port}"

    def start(self) -> "VirtualOPCServer":
        self._listener = socket.create_server(("127.0.0.1", self.port))
        self.port = self._listener.getsockname()[1]
        self._stopping.clear()
        self._thread = threading.Thread(target=self._serve, name="opc-sim", daemon=True)
        self._thread.start()
        return self

    def stop(self) -> None:
        self._stopping.set()
        if self._thread is not None:
            self._thread.join(timeout=2.0)
            self._thread = None
        self._close_all()

    def stall(self) -> None:
        """Fault: the server stops reading; clients' writes block once the buffers are full."""
        self._stalled.set()

    def disconnect(self) -> None:
        """Fault: the server goes away; clients' next writes fail."""
        self.stop()

    def __enter__(self):
        return self.start()

    def __exit__(self, *exc_info):
        self.stop()

    def board_pixels(self, count: int) -> np.ndarray:
        """The colours of the board's first ``count`` LEDs (output 0 holds 0..63)."""
        with self._lock:
            return self.board[:count].copy()

    def pixels_of(self, channel: int) -> np.ndarray:
        with self._lock:
            return self.pixels.get(channel, np.zeros((0, 3), np.uint8)).copy()

    def _serve(self) -> None:
        while not self._stopping.is_set():
            sockets = [self._listener] + ([] if self._stalled.is_set() else [*self._clients])
            try:
                ready, _, _ = select.select(sockets, [], [], _POLL_SECONDS)
            except (OSError, ValueError):
                return
            for sock in ready:
                if sock is self._listener:
                    client, _ = sock.accept()
                    self._clients[client] = bytearray()
                    continue
                try:
                    data = sock.recv(65536)
                except OSError:
                    data = b""
                if not data:
                    self._clients.pop(sock, None)
                    sock.close()
                    continue
                buffer = self._clients[sock]
                buffer += data
                for channel, command, payload in parse_messages(buffer):
                    self._handle(channel, command, payload)

    def _handle(self, channel: int, command: int, payload: bytes) -> None:
        with self._lock:
            self.messages.append((channel, command, payload))
            if command == SET_PIXELS:
                rgb = np.frombuffer(payload[:len(payload) // 3 * 3], np.uint8).reshape(-1, 3)
                self.pixels[channel] = rgb.copy()
                if channel == MAPPED_CHANNEL:
                    count = min(len(rgb), BOARD_PIXELS)
                    self.board[:count] = rgb[:count]

    def _close_all(self) -> None:
        for sock in [*self._clients, self._listener]:
            if sock is not None:
                try:
                    sock.shutdown(socket.SHUT_RDWR)
                except OSError:
                    pass
                sock.close()
        self._clients.clear()
        self._listener = None


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--port", type=int, default=0,
                        help="TCP port on 127.0.0.1 (default: a free one; fcserver uses 7890)")


def start(options: argparse.Namespace) -> VirtualOPCServer:
    return VirtualOPCServer(port=options.port).start()
