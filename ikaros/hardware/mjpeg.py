"""HTTP MJPEG streams: a reader with time-outs, and a small server on 127.0.0.1.

``MJPEGServer(frames)`` serves ``frames(n)`` (RGB ``uint8`` images) as an MJPEG stream
(``multipart/x-mixed-replace``, as network cameras send it) at ``url``, and one JPEG at
``url_snapshot``. Tests use it as a network camera; users can serve the synthetic scene::

    python -m ikaros.hardware.mjpeg --port 8080 --markers 1,2 --face

``MJPEGReader(url)`` reads such a stream frame by frame; every socket read has a time-out,
so a stream that stops makes ``read`` return None instead of waiting for ever.
"""
from __future__ import annotations

import argparse
import http.client
import socket
import threading
import time
import urllib.parse
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Callable

import numpy as np

from ._opencv import opencv

BOUNDARY = "ikarosframe"


def encode_jpeg(rgb: np.ndarray, quality: int = 90) -> bytes:
    cv2 = opencv()
    ok, data = cv2.imencode(".jpg", rgb[:, :, ::-1], [cv2.IMWRITE_JPEG_QUALITY, quality])
    return data.tobytes()


class MJPEGServer:
    """Serves frames as an MJPEG stream on 127.0.0.1 (port 0: a free port).

    ``frames(n)`` gives frame n (RGB uint8) or None when the stream should end. ``pause()``
    keeps connections open but sends nothing (a camera that hangs); ``resume()`` goes on;
    ``close()`` stops the server and ends every stream.
    """

    def __init__(self, frames: Callable[[int], np.ndarray | None], fps: float = 30.0,
                 port: int = 0, quality: int = 90, host: str = "127.0.0.1"):
        self.frames, self.fps, self.quality = frames, fps, quality
        self._running = threading.Event()
        self._running.set()
        self._closed = threading.Event()
        self.frames_sent = 0
        self.requests: list[str] = []       # the paths asked for, with their queries
        server = self

        class Handler(BaseHTTPRequestHandler):
            def log_message(self, *args):
                pass

            def do_GET(self):
                server.requests.append(self.path)
                path = urllib.parse.urlparse(self.path).path
                if path.endswith(".jpg"):
                    server._send_snapshot(self)
                else:
                    server._send_stream(self)

        self.httpd = ThreadingHTTPServer((host, port), Handler)
        self.httpd.daemon_threads = True
        self.port = self.httpd.server_address[1]
        self.url = f"http://{host}:{self.port}/video.mjpg"
        self.url_snapshot = f"http://{host}:{self.port}/snapshot.jpg"
        self._thread = threading.Thread(target=self.httpd.serve_forever, args=(0.05,),
                                        daemon=True, name="ikaros-mjpeg-server")
        self._thread.start()

    def _send_snapshot(self, handler):
        frame = self.frames(0)
        data = encode_jpeg(frame, self.quality)
        handler.send_response(200)
        handler.send_header("Content-Type", "image/jpeg")
        handler.send_header("Content-Length", str(len(data)))
        handler.end_headers()
        handler.wfile.write(data)

    def _send_stream(self, handler):
        handler.send_response(200)
        handler.send_header("Content-Type", f"multipart/x-mixed-replace; boundary={BOUNDARY}")
        handler.send_header("Cache-Control", "no-cache")
        handler.end_headers()
        n, start = 0, time.monotonic()
        try:
            while not self._closed.is_set():
                if not self._running.is_set():
                    self._closed.wait(0.02)
                    continue
                frame = self.frames(n)
                if frame is None:
                    return
                data = encode_jpeg(frame, self.quality)
                handler.wfile.write(f"--{BOUNDARY}\r\nContent-Type: image/jpeg\r\n"
                                    f"Content-Length: {len(data)}\r\n\r\n".encode())
                handler.wfile.write(data + b"\r\n")
                handler.wfile.flush()
                self.frames_sent += 1
                n += 1
                self._closed.wait(max(0.0, start + n / self.fps - time.monotonic()))
        except (BrokenPipeError, ConnectionResetError):
            return

    def pause(self):
        self._running.clear()

    def resume(self):
        self._running.set()

    def close(self):
        self._closed.set()
        self.httpd.shutdown()
        self.httpd.server_close()
        self._thread.join(timeout=2)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


class NotMJPEG(OSError):
    """The URL answers, but with neither an MJPEG stream nor a JPEG image."""


class MJPEGReader:
    """Reads an HTTP MJPEG stream (or polls a JPEG snapshot URL) frame by frame.

    ``read()`` returns the next frame as RGB uint8 (rows, cols, 3), or None when the stream
    ended or sent nothing for ``timeout`` seconds. Raises OSError when it cannot connect.
    """

    def __init__(self, url: str, timeout: float = 2.0):
        self.cv2 = opencv()
        self.url, self.timeout = url, timeout
        self._connect()

    def _connect(self):
        parts = urllib.parse.urlsplit(self.url)
        cls = http.client.HTTPSConnection if parts.scheme == "https" else http.client.HTTPConnection
        self._conn = cls(parts.hostname, parts.port, timeout=self.timeout)
        target = parts.path or "/"
        if parts.query:
            target += "?" + parts.query
        headers = {}
        if parts.username:
            import base64
            token = f"{parts.username}:{parts.password or ''}".encode()
            headers["Authorization"] = "Basic " + base64.b64encode(token).decode()
        self._conn.request("GET", target, headers=headers)
        self._socket = self._conn.sock          # the response keeps reading from it
        self._response = self._conn.getresponse()
        kind = self._response.getheader("Content-Type", "")
        self.multipart = kind.startswith("multipart/")
        if self._response.status != 200:
            self.close()
            raise OSError(f"HTTP {self._response.status} {self._response.reason}")
        if not self.multipart and not kind.startswith("image/"):
            self.close()
            raise NotMJPEG(f"not an MJPEG stream or a JPEG image (Content-Type {kind!r})")

    def _decode(self, data: bytes) -> np.ndarray | None:
        bgr = self.cv2.imdecode(np.frombuffer(data, np.uint8), self.cv2.IMREAD_COLOR)
        return None if bgr is None else bgr[:, :, ::-1]

    def read(self) -> np.ndarray | None:
        try:
            if not self.multipart:             # a snapshot URL: one image per request
                data = self._response.read()
                self._connect()
                return self._decode(data)
            return self._decode(self._next_part())
        except (OSError, http.client.HTTPException, EOFError):
            return None

    def _next_part(self) -> bytes:
        stream = self._response
        line = b""
        while not line.startswith(b"--"):       # skip to the next boundary
            line = stream.readline()
            if not line:
                raise EOFError
            line = line.strip()
        length = None
        while True:                             # the part's headers
            header = stream.readline()
            if not header:
                raise EOFError
            header = header.strip()
            if not header:
                break
            name, _, value = header.decode("latin-1").partition(":")
            if name.strip().lower() == "content-length":
                length = int(value)
        if length is not None:
            data = stream.read(length)
            if len(data) < length:
                raise EOFError
            return data
        data = bytearray()                      # no length: read to the JPEG's end marker
        while not data.endswith(b"\xff\xd9"):
            chunk = stream.read(1)
            if not chunk:
                raise EOFError
            data += chunk
        return bytes(data)

    def interrupt(self):
        """Make a read that waits on the stream return None now (from another thread)."""
        try:
            self._socket.shutdown(socket.SHUT_RDWR)
        except OSError:
            pass

    def close(self):
        try:
            self._response.close()
            self._conn.close()
        except OSError:
            pass


def main(argv=None):
    from .synthetic_camera import SyntheticScene
    p = argparse.ArgumentParser(description="Serve the synthetic camera scene as an MJPEG "
                                "stream (a network camera for testing models).")
    p.add_argument("--port", type=int, default=8080)
    p.add_argument("--size", default="640x480", help="COLSxROWS")
    p.add_argument("--fps", type=float, default=30)
    p.add_argument("--blobs", type=int, default=3)
    p.add_argument("--markers", default="", help="ArUco ids, e.g. 1,2,3")
    p.add_argument("--face", action="store_true")
    a = p.parse_args(argv)
    cols, rows = (int(v) for v in a.size.lower().split("x"))
    markers = [int(v) for v in a.markers.split(",") if v.strip()]
    scene = SyntheticScene(rows, cols, a.blobs, markers, a.face)
    with MJPEGServer(lambda n: scene.frame(n)[0], a.fps, a.port) as server:
        print(f"serving {server.url} (snapshot {server.url_snapshot}); Ctrl-C stops")
        try:
            while True:
                time.sleep(3600)
        except KeyboardInterrupt:
            pass


if __name__ == "__main__":
    main()
