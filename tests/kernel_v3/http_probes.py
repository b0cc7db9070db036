"""HTTP-framing probes of the kernel-test harness (catalogue rows 264, 266-269, 369).

Each probe talks to the web UI server at ``base`` over raw sockets, and raises
``ScriptFailure`` when the server does not answer as HTTP/1.1 (RFC 9112) says it should.
"""
from __future__ import annotations

import re
import socket
import struct
import time
from urllib.parse import urlsplit

KEEP_ALIVE = 5.0       # seconds uvicorn keeps an idle connection open (its default)


class ScriptFailure(Exception):
    """An action of the script did not give what it expects."""


def _connect(base: str) -> socket.socket:
    url = urlsplit(base)
    return socket.create_connection((url.hostname, url.port), timeout=5)


def _request(path: str, method: str = "GET", extra: str = "") -> bytes:
    return f"{method} {path} HTTP/1.1\r\nHost: 127.0.0.1\r\n{extra}\r\n".encode()


def _read(sock: socket.socket, seconds: float = 2.0) -> tuple[bytes, bool]:
    """What the server sends within ``seconds``, and whether it closed the connection."""
    sock.settimeout(0.2)
    data, deadline = b"", time.monotonic() + seconds
    while time.monotonic() < deadline:
        try:
            chunk = sock.recv(65536)
        except socket.timeout:
            continue
        if not chunk:
            return data, True
        data += chunk
    return data, False


def _statuses(data: bytes) -> list[int]:
    return [int(code) for code in re.findall(rb"HTTP/1\.1 (\d{3}) ", data)]


def _expect(what: str, found, expected):
    if found != expected:
        raise ScriptFailure(f"{what}: {found!r}, expected {expected!r}")


def split_request(base: str):
    """A request line and headers arriving in four TCP segments get one 200."""
    with _connect(base) as sock:
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        for part in (b"GET /api/st", b"atus HTTP/1.1\r\nHo", b"st: 127.0.0.1\r\n",
                     b"Connection: close\r\n\r\n"):
            sock.sendall(part)
            time.sleep(0.05)
        data, closed = _read(sock)
    _expect("split request", (_statuses(data), b'"state"' in data, closed),
            ([200], True, True))


def pipelined(base: str):
    """Three requests sent at once on one connection are answered in order."""
    with _connect(base) as sock:
        sock.sendall(_request("/api/status") + _request("/api/network") +
                     _request("/no/such/path", extra="Connection: close\r\n"))
        data, closed = _read(sock)
    _expect("pipelined requests", (_statuses(data), closed), ([200, 200, 404], True))
    if data.index(b'"state"') > data.index(b'"top"'):
        raise ScriptFailure("pipelined requests answered out of order")


def keep_alive_timeout(base: str):
    """An idle keep-alive connection is closed after KEEP_ALIVE seconds, not before."""
    with _connect(base) as sock:
        sock.sendall(_request("/api/status"))
        start = time.monotonic()
        data, closed = _read(sock, KEEP_ALIVE + 2)
        took = time.monotonic() - start
    _expect("keep-alive", (_statuses(data), closed), ([200], True))
    if not KEEP_ALIVE - 0.5 <= took <= KEEP_ALIVE + 1.5:
        raise ScriptFailure(f"idle connection closed after {took:.2f} s")


def framing(base: str):
    """A body framed by Content-Length is read exactly (the next request on the connection
    is answered too); Content-Length with Transfer-Encoding, two different lengths and a
    length that is no number are refused with 400 and the connection closed."""
    body = b'{"since": 0}'
    with _connect(base) as sock:       # a POST to a GET route: 405, the body skipped
        sock.sendall(_request("/api/log", "POST", f"Content-Type: application/json\r\n"
                              f"Content-Length: {len(body)}\r\n") + body +
                     _request("/api/status", extra="Connection: close\r\n"))
        data, closed = _read(sock)
    _expect("a framed body, then a request", (_statuses(data), closed), ([405, 200], True))
    for headers in ("Content-Length: 5\r\nTransfer-Encoding: chunked\r\n",
                    "Transfer-Encoding: chunked\r\nContent-Length: 5\r\n",
                    "Content-Length: 5\r\nContent-Length: 6\r\n",
                    "Content-Length: abc\r\n"):
        with _connect(base) as sock:
            sock.sendall(_request("/api/control", "POST",
                                  "Content-Type: application/json\r\n" + headers) +
                         b"0\r\n\r\n" + _request("/api/status"))
            data, closed = _read(sock)
        _expect(f"ambiguous framing {headers!r}", (_statuses(data), closed), ([400], True))


def error_responses(base: str):
    """Malformed or unsupported requests get an explicit 4xx or 5xx, each on its own."""
    close = "Connection: close\r\n"       # answered at once, not after the keep-alive
    cases = [
        (b"GARBAGE\r\n\r\n", 400),                                       # no request line
        (b"GET /api/status HTTP/1.1\r\n\r\n", 400),                      # no Host
        (b"GET /api/status HTTP/1.1\r\nHost 127.0.0.1\r\n\r\n", 400),    # a header without :
        (b"GET /api/status HTTP/1.7\r\nHost: 127.0.0.1\r\n\r\n", 505),   # unknown version
        (_request("/api/status", "BREW", close), 405),                   # unknown method
        (_request("/api/control", "GET", close), 405),                   # wrong method
        (_request("/api/nothing", extra=close), 404),                    # no such path
        (_request("/api/control", "POST", close + "Content-Type: application/json\r\n"
                  "Content-Length: 7\r\n") + b'{"st": ', 400),            # invalid JSON
        (_request("/api/control", "POST", close + "Content-Type: text/plain\r\n"
                  "Content-Length: 2\r\n") + b"{}", 415),                # not JSON
    ]
    for request, status in cases:
        with _connect(base) as sock:
            sock.sendall(request)
            data, _ = _read(sock, 1.0)
        _expect(f"answer to {request[:40]!r}", _statuses(data)[:1], [status])


def connection_reset(base: str):
    """Clients that reset their connection (half a request, or before reading the answer)
    are a normal disconnect: the server goes on answering."""
    reset = struct.pack("ii", 1, 0)            # SO_LINGER 0: close sends RST
    for request in (b"GET /api/sta", _request("/api/network")):
        sock = _connect(base)
        sock.sendall(request)
        time.sleep(0.1)
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, reset)
        sock.close()
    with _connect(base) as sock:
        sock.sendall(_request("/api/status", extra="Connection: close\r\n"))
        data, _ = _read(sock)
    _expect("a request after the resets", _statuses(data), [200])


PROBES = {"split_request": split_request, "pipelined": pipelined,
          "keep_alive_timeout": keep_alive_timeout, "framing": framing,
          "error_responses": error_responses, "connection_reset": connection_reset}
