"""A simulated Eye Tribe server on 127.0.0.1: answers the push request and heartbeats as the
tracker server does and pushes the frames it is given. Every message ends with a newline, as
the server's do."""
from __future__ import annotations

import json
import socket
import threading
import time

from .eyetribe import messages


def frame(time_ms: int, x: float, y: float, fix: bool = False, pupil: float = 20.0) -> dict:
    """A frame as the tracker sends it, with both eyes at (x, y) ± 10 pixels."""
    def eye(dx):
        return {"raw": {"x": x + dx, "y": y}, "avg": {"x": x + dx, "y": y}, "psize": pupil,
                "pcenter": {"x": 0.5 + dx / 1000, "y": 0.5}}
    return {"timestamp": time.strftime("%Y-%m-%d %H:%M:%S.000"), "time": time_ms, "fix": fix,
            "state": 7, "raw": {"x": x, "y": y}, "avg": {"x": x, "y": y},
            "lefteye": eye(-10), "righteye": eye(10)}


class SimulatedEyeTribe:
    """A tracker server on 127.0.0.1 (a free port unless given). ``push(frame)`` sends a
    frame to the connected client once it has asked for pushed frames; ``requests`` lists
    what the client sent; ``drop()`` closes the client's connection."""

    def __init__(self, port: int = 0):
        self.server = socket.create_server(("127.0.0.1", port))
        self.port = self.server.getsockname()[1]
        self.requests: list[dict] = []
        self.client: socket.socket | None = None
        self.pushing = threading.Event()
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._serve, daemon=True)
        self._thread.start()

    def _serve(self) -> None:
        self.server.settimeout(0.1)
        while not self._stop.is_set():
            try:
                client, _ = self.server.accept()
            except socket.timeout:
                continue
            self.client = client
            client.settimeout(0.1)
            buffer = ""
            while not self._stop.is_set():
                try:
                    data = client.recv(4096)
                except socket.timeout:
                    continue
                except OSError:
                    break
                if not data:
                    break
                found, buffer, _ = messages(buffer + data.decode())
                for request in found:
                    self.requests.append(request)
                    self._answer(client, request)
            self.pushing.clear()
            client.close()
            self.client = None

    def _answer(self, client, request: dict) -> None:
        reply = {"category": request.get("category"), "statuscode": 200}
        if request.get("request"):
            reply["request"] = request["request"]
        if request.get("request") == "set" and request.get("values", {}).get("push"):
            reply["values"] = {}
            self.pushing.set()
        client.sendall(json.dumps(reply).encode() + b"\n")

    def push(self, gaze: dict) -> None:
        self.pushing.wait(5)
        message = {"category": "tracker", "request": "get", "statuscode": 200,
                   "values": {"frame": gaze}}
        self.client.sendall(json.dumps(message).encode() + b"\n")

    def send_text(self, text: str) -> None:
        """Send raw text to the client (a fault: a message that is no JSON, or one cut off)."""
        self.pushing.wait(5)
        self.client.sendall(text.encode())

    def drop(self) -> None:
        if self.client is not None:
            self.client.shutdown(socket.SHUT_RDWR)

    def close(self) -> None:
        self._stop.set()
        self._thread.join(2)
        self.server.close()
