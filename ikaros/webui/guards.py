"""Guards on what clients send: the size of request bodies and the nesting of JSON, both
checked before anything is decoded (so no request can exhaust memory or the stack); and
quiet logs for WebSockets refused on purpose and for clients that go away mid-request."""
from __future__ import annotations

import logging
import re
import sys

import numpy as np
from starlette.responses import Response

DEFAULT_MAX_BODY = 4 << 20     # bytes of one request body or WebSocket message
MAX_JSON_DEPTH = 512           # nesting of arrays and objects (a model tree needs ~2 per level)

_STRING = re.compile(rb'"(?:[^"\\]|\\.)*"', re.S)
_OPEN, _CLOSE = b"[{", b"]}"


class BodyTooLarge(Exception):
    """A request body larger than the limit (answered with 413)."""

    def __init__(self, limit: int):
        super().__init__(f"the request body is larger than the limit of {limit} bytes")


def json_depth(raw: bytes | str) -> int:
    """The deepest nesting of arrays and objects in a JSON text (strings skipped)."""
    if isinstance(raw, str):
        raw = raw.encode("utf-8", "surrogatepass")
    if b"[" not in raw and b"{" not in raw:
        return 0
    brackets = _STRING.sub(b"", raw).translate(None, delete=bytes(
        c for c in range(256) if c not in b"[]{}"))
    codes = np.frombuffer(brackets, dtype=np.uint8)
    steps = np.where((codes == ord("[")) | (codes == ord("{")), 1, -1)
    return int(np.cumsum(steps).max(initial=0))


class BodyLimit:
    """ASGI middleware: HTTP request bodies over ``limit`` bytes get 413 (by their
    Content-Length at once, else as they stream in)."""

    def __init__(self, app, limit: int = DEFAULT_MAX_BODY, too_large=None):
        self.app = app
        self.limit = limit
        self.too_large = too_large     # an ASGI app answering 413

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        for key, value in scope.get("headers", []):
            if key.lower() == b"content-length":
                try:
                    length = int(value)
                except ValueError:
                    length = 0
                if length > self.limit:
                    return await self.too_large(scope, receive, send)
        seen = 0
        limit = self.limit

        async def counted():
            nonlocal seen
            message = await receive()
            if message["type"] == "http.request":
                seen += len(message.get("body", b""))
                if seen > limit:
                    raise BodyTooLarge(limit)
            return message
        return await self.app(scope, counted, send)


class Framing:
    """ASGI middleware refusing requests whose framing is ambiguous or unsupported, before
    anything reads them: both ``Content-Length`` and ``Transfer-Encoding`` (a request
    smuggling form, RFC 9112 §6.3) is 400, an HTTP version other than 1.0 and 1.1 is 505.
    Both answers close the connection. (uvicorn itself refuses malformed request lines,
    headers and lengths with 400.)"""

    def __init__(self, app, answer):
        self.app = app
        self.answer = answer            # answer(status, message) -> an ASGI app

    async def __call__(self, scope, receive, send):
        if scope["type"] == "http":
            names = {key.lower() for key, _ in scope.get("headers", [])}
            if scope.get("http_version") not in ("1.0", "1.1"):
                refusal = (505, f'HTTP version {scope.get("http_version")} is not supported')
            elif b"content-length" in names and b"transfer-encoding" in names:
                refusal = (400, "a request must not have both Content-Length and "
                                "Transfer-Encoding")
            else:
                refusal = None
            if refusal:
                return await self.answer(*refusal)(scope, receive, send)
        return await self.app(scope, receive, send)


class _RefusedWebSocket(logging.Filter):
    """uvicorn logs an error when a WebSocket is answered with an HTTP response (as
    AccessMiddleware refuses one); that is no error of the server."""

    def filter(self, record) -> bool:
        return record.getMessage() != "ASGI callable returned without completing handshake."


def quiet_refused_websockets() -> None:
    """Keep refused WebSockets out of the server's error log."""
    log = logging.getLogger("uvicorn.error")
    if not any(isinstance(f, _RefusedWebSocket) for f in log.filters):
        log.addFilter(_RefusedWebSocket())


async def client_gone(request, error) -> Response:
    """A client that went away before sending the whole body its Content-Length promised
    (starlette's ClientDisconnect): one line in the log, not a traceback; the answer goes
    nowhere."""
    print(f"ikaros: web UI: {request.method} {request.url.path}: the client went away "
          f"before sending the whole request", file=sys.stderr, flush=True)
    return Response(status_code=400)
