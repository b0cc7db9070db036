"""WebSocket actions of the kernel-test harness (our web UI pushes data and log messages
on ``/api/ws`` where Ikaros 3 answers polls of ``/update``; docs/webui-protocol.md).

* ``ws_first_frame:BUFFER:VALUE``: a new client subscribes to BUFFER; its first data frame
  holds VALUE, taken at tick VALUE (a buffer counting the ticks run);
* ``ws_coherent:A:B``: a client subscribed to A, then to A and B: every frame has A and B
  equal to its tick (buffers counting the ticks run);
* ``ws_max_frames:BUFFER:S:MAX``: a client that says ``ready`` at once after every frame
  gets between 2 and MAX frames, of distinct ticks, in S seconds;
* ``ws_open:N``: N clients connect and collect the log messages they are sent;
* ``ws_log_count:TEXT:N``: each open client has been sent TEXT in exactly N messages.
"""
from __future__ import annotations

import contextlib
import json
import struct
import threading
import time

import numpy as np
from websockets.exceptions import WebSocketException
from websockets.sync.client import connect

from http_probes import ScriptFailure

__all__ = ["WebSocketException", "LogClients", "coherent", "first_frame", "max_frames"]

FRAME_TIMEOUT = 5.0        # seconds to wait for a data frame
LOG_SETTLE = 0.5           # seconds for more log messages to come (they are sent 5 a second)


def _frame(ws) -> tuple[dict, dict]:
    """The next data frame: (header, {path: values as a flat float32 array})."""
    deadline = time.monotonic() + FRAME_TIMEOUT
    while time.monotonic() < deadline:
        message = ws.recv(timeout=max(0.01, deadline - time.monotonic()))
        if isinstance(message, bytes):
            (length,) = struct.unpack_from("<I", message)
            header = json.loads(message[4:4 + length])
            payload = message[4 + length:]
            values = {b["path"]: np.frombuffer(payload, "<f4", b["length"] // 4, b["offset"])
                      for b in header["buffers"]}
            return header, values
    raise ScriptFailure(f"no data frame within {FRAME_TIMEOUT:g} s")


def _subscribe(ws, paths: list[str]):
    ws.send(json.dumps({"type": "subscribe",
                        "buffers": [{"path": p, "format": "raw"} for p in paths]}))
    ws.send(json.dumps({"type": "ready"}))


def _ws_url(base: str) -> str:
    return base.replace("http://", "ws://") + "/api/ws"


def first_frame(base: str, buffer: str, value: str):
    with connect(_ws_url(base), open_timeout=5) as ws:
        _subscribe(ws, [buffer])
        header, values = _frame(ws)
    found = (header["tick"], values[buffer].tolist())
    if found != (int(value), [float(value)]):
        raise ScriptFailure(f"first frame: tick {found[0]}, {buffer} = {found[1]}")


def coherent(base: str, first: str, second: str):
    with connect(_ws_url(base), open_timeout=5) as ws:
        _subscribe(ws, [first])
        header, values = _frame(ws)
        if values[first].tolist() != [header["tick"]]:
            raise ScriptFailure(f"{first} = {values[first]} at tick {header['tick']}")
        _subscribe(ws, [first, second])
        for _ in range(3):
            header, values = _frame(ws)
            if second in values:
                break
            ws.send(json.dumps({"type": "ready"}))
        else:
            raise ScriptFailure(f"no frame with {second} after the new subscription")
        found = [values[first].tolist(), values[second].tolist()]
        if found != [[header["tick"]]] * 2:
            raise ScriptFailure(f"{first}, {second} = {found} at tick {header['tick']}")


def max_frames(base: str, buffer: str, seconds: str, most: str):
    ticks = []
    with connect(_ws_url(base), open_timeout=5) as ws:
        _subscribe(ws, [buffer])
        deadline = time.monotonic() + float(seconds)
        while time.monotonic() < deadline:
            try:
                message = ws.recv(timeout=max(0.01, deadline - time.monotonic()))
            except TimeoutError:
                break
            if isinstance(message, bytes):
                (length,) = struct.unpack_from("<I", message)
                ticks.append(json.loads(message[4:4 + length])["tick"])
                ws.send(json.dumps({"type": "ready"}))
    if not 2 <= len(ticks) <= int(most) or len(set(ticks)) != len(ticks):
        raise ScriptFailure(f"{len(ticks)} frames in {seconds} s (ticks {ticks}), "
                            f"expected 2 to {most} of distinct ticks")


class LogClients:
    """WebSocket clients that collect the log messages they are sent."""

    def __init__(self):
        self.sockets, self.messages, self.threads = [], [], []
        self._stack = contextlib.ExitStack()

    def open(self, base: str, count: int):
        for _ in range(count):
            ws = self._stack.enter_context(connect(_ws_url(base), open_timeout=5))
            received: list[str] = []
            thread = threading.Thread(target=self._collect, args=(ws, received), daemon=True)
            thread.start()
            self.sockets.append(ws)
            self.messages.append(received)
            self.threads.append(thread)

    @staticmethod
    def _collect(ws, received: list[str]):
        try:
            for message in ws:
                if isinstance(message, str):
                    msg = json.loads(message)
                    if msg.get("type") == "log":
                        received.extend(m["message"] for m in msg["messages"])
        except Exception:           # closed
            pass

    def count(self, text: str, times: int):
        if not self.sockets:
            raise ScriptFailure("ws_log_count: no client is open (ws_open:N first)")
        def counts():
            return [sum(text in m for m in list(received)) for received in self.messages]
        deadline = time.monotonic() + FRAME_TIMEOUT
        while min(counts()) < times and time.monotonic() < deadline:
            time.sleep(0.05)
        time.sleep(LOG_SETTLE)          # time for a message sent twice to come again
        found = counts()
        if found != [times] * len(found):
            raise ScriptFailure(f"clients were sent {text!r} {found} times, expected {times}")

    def close(self):
        self._stack.close()
        for thread in self.threads:
            thread.join(2)
