"""A front for the live Foxglove view that also admits clients of the protocol's old name.

Foxglove's WebSocket protocol was named ``foxglove.websocket.v1``; the Foxglove SDK names it
``foxglove.sdk.v1`` and refuses a client that offers only the old name (HTTP 400), although
the messages are the same. Older Foxglove and Lichtblick versions, and other clients written
for foxglove_bridge before 3.x, offer only the old name. This front listens on the view's
port and passes each connection through to the SDK's server on a loopback port of its own:
in the opening handshake, an offer of the old name alone is presented to the server as the
new name, and the server's answer names the old one again; every byte after the handshake
passes unchanged.
"""
from __future__ import annotations

import re
import socket
import threading

OLD, NEW = "foxglove.websocket.v1", "foxglove.sdk.v1"
HEADER_LIMIT = 65536            # an opening handshake longer than this is refused
HANDSHAKE_SECONDS = 10.0
_PROTOCOL = re.compile(rb"^(sec-websocket-protocol:[ \t]*)(.*?)\r$", re.I | re.M)


def _offered(head: bytes) -> list[str]:
    return [p.strip() for m in _PROTOCOL.finditer(head)
            for p in m.group(2).decode("latin-1").split(",")]


def rewrite_request(head: bytes) -> tuple[bytes, bool]:
    """The client's handshake as the server should see it, and whether the client spoke
    the old name only."""
    offered = _offered(head)
    if NEW in offered or OLD not in offered:
        return head, False
    return _PROTOCOL.sub(lambda m: m.group(1) + m.group(2).replace(OLD.encode(), NEW.encode())
                         + b"\r", head), True


def rewrite_response(head: bytes) -> bytes:
    """The server's answer, naming the old protocol the client asked for."""
    return _PROTOCOL.sub(lambda m: m.group(1) + m.group(2).replace(NEW.encode(), OLD.encode())
                         + b"\r", head)


def _read_head(sock: socket.socket) -> tuple[bytes, bytes]:
    """An HTTP head (up to and with the blank line) and what came after it."""
    data = b""
    while b"\r\n\r\n" not in data:
        chunk = sock.recv(4096)
        if not chunk or len(data) > HEADER_LIMIT:
            raise ConnectionError("no complete handshake")
        data += chunk
    end = data.index(b"\r\n\r\n") + 4
    return data[:end], data[end:]


def _pump(source: socket.socket, sink: socket.socket) -> None:
    try:
        while chunk := source.recv(65536):
            sink.sendall(chunk)
    except OSError:
        pass
    finally:
        for s in (sink, source):
            try:
                s.shutdown(socket.SHUT_RDWR)
            except OSError:
                pass


class SubprotocolFront:
    """Listens on ``host:port`` (0: a free port, in ``self.port``) and passes connections to
    the server at ``127.0.0.1:upstream``, admitting clients of either protocol name."""

    def __init__(self, upstream: int, host: str = "127.0.0.1", port: int = 0):
        self.upstream = upstream
        self._listener = socket.create_server((host, port))
        self.port = self._listener.getsockname()[1]
        self._connections: list[socket.socket] = []
        self._lock = threading.Lock()
        self._closed = False
        threading.Thread(target=self._accept, name="ikaros-foxglove-front",
                         daemon=True).start()

    def _accept(self) -> None:
        while True:
            try:
                client, _ = self._listener.accept()
            except OSError:
                return
            threading.Thread(target=self._serve, args=(client,), daemon=True).start()

    def _serve(self, client: socket.socket) -> None:
        server = None
        try:
            client.settimeout(HANDSHAKE_SECONDS)
            head, rest = _read_head(client)
            head, old_name = rewrite_request(head)
            server = socket.create_connection(("127.0.0.1", self.upstream),
                                              timeout=HANDSHAKE_SECONDS)
            server.sendall(head + rest)
            answer, rest = _read_head(server)
            client.sendall((rewrite_response(answer) if old_name else answer) + rest)
            client.settimeout(None)
            server.settimeout(None)
        except (OSError, ConnectionError):
            for s in (client, server):
                if s is not None:
                    s.close()
            return
        with self._lock:
            if self._closed:
                client.close()
                server.close()
                return
            self._connections += [client, server]
        back = threading.Thread(target=_pump, args=(server, client), daemon=True)
        back.start()
        _pump(client, server)
        back.join()
        with self._lock:
            self._connections = [s for s in self._connections if s not in (client, server)]
        client.close()
        server.close()

    def close(self) -> None:
        """Stop listening and end every connection."""
        with self._lock:
            self._closed = True
            connections, self._connections = self._connections, []
        self._listener.close()
        for s in connections:
            try:
                s.shutdown(socket.SHUT_RDWR)
            except OSError:
                pass
            s.close()
