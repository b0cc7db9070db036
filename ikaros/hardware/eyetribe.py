"""The Eye Tribe tracker's API: JSON messages over TCP (port 6555 of the tracker server).

The client asks the server to push frames (``{"category": "tracker", "request": "set",
"values": {"push": true, "version": 1}}``), sends a heartbeat (``{"category": "heartbeat"}``)
every 250 ms, and keeps the newest frame it received. Messages are JSON objects, each ended
by a newline (The Eye Tribe "API Reference", "Protocol" and "Tracker" categories); they are
read whether or not the newline has come. Text that is no JSON object, and a message cut
off (its line ends before it closes), is skipped and kept for a
warning, and reading resumes at the next message at once.
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
    object: text before a ``{``, a ``{...}`` whose braces balance but that does not parse, or
    a message cut off. The server ends every message with a newline, and JSON holds no raw
    newline inside a message, so a ``{`` still open at a newline is a message cut off (a
    connection hiccup): it is skipped, and reading resumes at the next ``{`` of that line
    from which a whole JSON object reads (the next message, sent right after the cut one),
    or after the newline. A ``{...}`` that does not parse is skipped to the next ``{`` in it.
    So a bad or truncated message costs that message alone. An unfinished message longer
    than ``MAX_PENDING`` is skipped too, so the buffer stays bounded."""
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
        end, cut = _closing_brace(buffer, start)
        if cut:                                      # cut off: resynchronise in its line
            stop = _next_message(decoder, buffer, start, end)
            skipped.append(buffer[start:stop].strip())
            i = stop
            continue
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


def _next_message(decoder: json.JSONDecoder, text: str, start: int, newline: int) -> int:
    """Where reading resumes after the message cut off at ``start``: the first later ``{``
    before ``newline`` from which a whole JSON object reads within the line, else the
    newline."""
    k = text.find("{", start + 1, newline)
    while k >= 0:
        try:
            obj, end = decoder.raw_decode(text, k)
        except json.JSONDecodeError:
            obj, end = None, newline + 1
        if isinstance(obj, dict) and end <= newline:
            return k
        k = text.find("{", k + 1, newline)
    return newline


def _closing_brace(text: str, start: int) -> tuple[int | None, bool]:
    """(the index after the ``}`` that closes the ``{`` at ``start``, False) — braces in JSON
    strings do not count — or (the index of a newline met first, True), or (None, False)
    when the text ends first."""
    depth, in_string, escaped = 0, False, False
    for k in range(start, len(text)):
        c = text[k]
        if c == "\n":
            return k, True
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
                return k + 1, False
    return None, False


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
