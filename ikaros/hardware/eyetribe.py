"""The Eye Tribe tracker's API: JSON messages over TCP (port 6555 of the tracker server).

The client asks the server to push frames (``{"category": "tracker", "request": "set",
"values": {"push": true, "version": 1}}``), sends a heartbeat (``{"category": "heartbeat"}``)
every 250 ms, and keeps the newest frame it received. Frames are JSON objects sent one after
the other, not necessarily one per line.
"""
from __future__ import annotations

import json
import socket
import threading
import time

from .. import priority

PORT = 6555
HEARTBEAT_SECONDS = 0.25
PUSH_REQUEST = {"category": "tracker", "request": "set", "values": {"push": True,
                                                                    "version": 1}}
HEARTBEAT = {"category": "heartbeat"}


def messages(buffer: str) -> tuple[list[dict], str]:
    """The whole JSON objects at the start of ``buffer``, and what is left after them."""
    decoder = json.JSONDecoder()
    found, i = [], 0
    while True:
        while i < len(buffer) and buffer[i].isspace():
            i += 1
        if i >= len(buffer):
            return found, ""
        try:
            obj, end = decoder.raw_decode(buffer, i)
        except json.JSONDecodeError:
            return found, buffer[i:]
        if isinstance(obj, dict):
            found.append(obj)
        i = end


def frame_of(message: dict) -> dict | None:
    """The gaze frame a tracker message carries, or None."""
    if message.get("category") != "tracker":
        return None
    values = message.get("values")
    return values.get("frame") if isinstance(values, dict) else None


class EyeTribeClient:
    """Connects to an Eye Tribe server and keeps its newest frame (``frame``, ``frames``:
    how many came). A lost server is retried every second; ``error`` says what went wrong
    last (None while connected)."""

    def __init__(self, host: str = "127.0.0.1", port: int = PORT, timeout: float = 2.0):
        self.host, self.port, self.timeout = host, port, timeout
        self.frame: dict | None = None
        self.frames = 0
        self.error: str | None = None
        self.lock = threading.Lock()
        self._stop = threading.Event()
        self._socket = self._connect()          # the first attempt fails at once
        self._thread = threading.Thread(target=self._run, daemon=True,
                                        name="ikaros-eyetribe")
        self._thread.start()

    def _connect(self) -> socket.socket:
        s = socket.create_connection((self.host, self.port), timeout=self.timeout)
        s.settimeout(HEARTBEAT_SECONDS)
        s.sendall(json.dumps(PUSH_REQUEST).encode())
        return s

    def _run(self) -> None:
        priority.device_thread()
        s, buffer, last_beat = self._socket, "", 0.0
        while not self._stop.is_set():
            try:
                if s is None:
                    s, buffer = self._connect(), ""
                    self.error = None
                now = time.monotonic()
                if now - last_beat >= HEARTBEAT_SECONDS:
                    s.sendall(json.dumps(HEARTBEAT).encode())
                    last_beat = now
                try:
                    data = s.recv(65536)
                except socket.timeout:
                    continue
                if not data:
                    raise ConnectionError("the tracker server closed the connection")
                found, buffer = messages(buffer + data.decode("utf-8", "replace"))
                for message in found:
                    frame = frame_of(message)
                    if frame is not None:
                        with self.lock:
                            self.frame = frame
                            self.frames += 1
            except OSError as e:
                self.error = f"{type(e).__name__}: {e}"
                if s is not None:
                    s.close()
                s = None
                self._stop.wait(1.0)
        if s is not None:
            s.close()

    def newest(self) -> tuple[dict | None, int]:
        with self.lock:
            return self.frame, self.frames

    def close(self) -> None:
        self._stop.set()
        self._thread.join(2 * HEARTBEAT_SECONDS + self.timeout)
