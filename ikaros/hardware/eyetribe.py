"""The Eye Tribe tracker's API: JSON messages over TCP (port 6555 of the tracker server).

The client asks the server to push frames (``{"category": "tracker", "request": "set",
"values": {"push": true, "version": 1}}``), sends a heartbeat (``{"category": "heartbeat"}``)
every 250 ms, and keeps the newest frame it received. Frames are JSON objects sent one after
the other, not necessarily one per line (The Eye Tribe "API Reference", "Protocol" and
"Tracker" categories). Text that is no JSON object is skipped and kept for a warning, and
reading resumes at the next message.
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


MAX_PENDING = 65536              # characters of an unfinished message kept (a frame is < 1000)


def messages(buffer: str) -> tuple[list[dict], str, list[str]]:
    """The whole JSON objects at the start of ``buffer``, what is left after them (the start
    of an unfinished message), and the pieces of text skipped because they are no JSON
    object: text before a ``{``, or a ``{...}`` whose braces balance but that does not parse.
    Parsing resumes at the next ``{``; an unfinished message longer than ``MAX_PENDING`` is
    skipped too, so the buffer stays bounded."""
    decoder = json.JSONDecoder()
    found: list[dict] = []
    skipped: list[str] = []
    i = 0
    while True:
        start = buffer.find("{", i)
        if start < 0:
            start = len(buffer)
        if buffer[i:start].strip():
            skipped.append(buffer[i:start].strip())
        if start >= len(buffer):
            return found, "", skipped
        end = _closing_brace(buffer, start)
        if end is None:                              # unfinished: wait for the rest
            if len(buffer) - start > MAX_PENDING:
                skipped.append(buffer[start:])
                return found, "", skipped
            return found, buffer[start:], skipped
        try:
            obj, _ = decoder.raw_decode(buffer[start:end])
        except json.JSONDecodeError:
            obj = None
        if isinstance(obj, dict):
            found.append(obj)
            i = end
        else:                                        # not JSON: resynchronise after its '{'
            following = buffer.find("{", start + 1)
            stop = end if following < 0 or following >= end else following
            skipped.append(buffer[start:stop])
            i = stop


def _closing_brace(text: str, start: int) -> int | None:
    """The index after the ``}`` that closes the ``{`` at ``start`` (braces in JSON strings
    do not count), or None when the text ends first."""
    depth, in_string, escaped = 0, False, False
    for k in range(start, len(text)):
        c = text[k]
        if in_string:
            if escaped:
                escaped = False
            elif c == "\\":
                escaped = True
            elif c == '"':
                in_string = False
        elif c == '"':
            in_string = True
        elif c == "{":
            depth += 1
        elif c == "}":
            depth -= 1
            if depth == 0:
                return k + 1
    return None


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
        self.skipped: list[str] = []            # text that was no message (see take_skipped)
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
                found, buffer, skipped = messages(buffer + data.decode("utf-8", "replace"))
                if skipped:
                    with self.lock:
                        self.skipped.extend(skipped)
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

    def take_skipped(self) -> list[str]:
        """The pieces of text skipped since the last call (they were no JSON message)."""
        with self.lock:
            skipped, self.skipped = self.skipped, []
        return skipped

    def newest(self) -> tuple[dict | None, int]:
        with self.lock:
            return self.frame, self.frames

    def close(self) -> None:
        self._stop.set()
        self._thread.join(2 * HEARTBEAT_SECONDS + self.timeout)
