"""Hostile models and requests against a real server (``ikaros -w 0``) whose memory is
limited: the exact errors of /api/apply, 400 for JSON nested too deep (HTTP and WebSocket),
413 for large bodies, a build that never returns (its request times out, later applies go
on, Ctrl-C still ends the process), and never a 500 or a traceback."""
from __future__ import annotations

import json
import os
import resource
import signal
import subprocess
import sys
import time
import urllib.error
import urllib.request

import pytest

from ikaros.language.reader import read_file
from ikaros.webui import editing

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
sys.path.insert(0, os.path.join(ROOT, "tests", "hostile"))
from hostile_cases import BUILD_ERRORS, MAX_MEMORY, generate  # noqa: E402

ADDRESS_SPACE = 2 << 30
START = '<group name="Start"><module class="Constant" name="C" data="1 2"/></group>\n'
# Errors that the reader gives before a tree is made: sent as trees, they fail otherwise.
NOT_AS_TREES = {"nest_500", "nest_2000", "nest_20000", "include_text"}


def _limited():
    resource.setrlimit(resource.RLIMIT_AS, (ADDRESS_SPACE, ADDRESS_SPACE))


class Server:
    def __init__(self, folder, *extra):
        env = dict(os.environ, PYTHONPATH=ROOT, OPENBLAS_NUM_THREADS="1")
        self.proc = subprocess.Popen(
            [sys.executable, "-m", "ikaros", "-w", "0", "--max-memory", MAX_MEMORY,
             "--models", folder, *extra, os.path.join(folder, "start.ikg")],
            cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
            preexec_fn=_limited)
        line = self.proc.stdout.readline()
        assert " at http://127.0.0.1:" in line, line + self.proc.stderr.read()
        self.url = line.split(" at ")[1].split()[0].rstrip("/")

    def post(self, path, body, timeout=30, raw=False):
        data = body if raw else json.dumps(body).encode()
        request = urllib.request.Request(self.url + path, data=data, method="POST",
                                         headers={"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(request, timeout=timeout) as r:
                return r.status, json.load(r)
        except urllib.error.HTTPError as e:
            return e.code, json.loads(e.read() or b"{}")

    def stop(self, timeout=10):
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGINT)
        try:
            out, err = self.proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            out, err = self.proc.communicate()
            raise AssertionError("the server did not stop on SIGINT") from None
        return self.proc.returncode, out, err


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    d = str(tmp_path_factory.mktemp("hostile"))
    generate(d)
    with open(os.path.join(d, "start.ikg"), "w") as f:
        f.write(START)
    return d


@pytest.fixture(scope="module")
def server(folder):
    s = Server(folder, "--build-timeout", "2")
    yield s
    status, _, err = s.stop()
    # no traceback, no error logged (refused WebSockets too); only the notes on the
    # dialect of the models applied (their Print is Ikaros 3's)
    assert [line for line in err.splitlines() if ": note: read as an Ikaros" not in line] == []
    assert status == 0, err


def _as_tree(path):
    return editing.tree_json(read_file(path), os.path.dirname(path))


@pytest.mark.parametrize("name", sorted(set(BUILD_ERRORS) - NOT_AS_TREES))
def test_apply_of_a_hostile_model_gives_its_error(server, folder, name):
    start = time.monotonic()
    status, body = server.post("/api/apply", {"tree": _as_tree(
        os.path.join(folder, f"{name}.ikg"))})
    assert time.monotonic() - start < 10
    assert status == 422, body
    expected = BUILD_ERRORS[name].format(dir=folder)
    if name != "Selfish":       # (its error is in the class file Selfish.ikg)
        # the tree applied is the running model's: errors in it name start.ikg
        expected = expected.replace(f"{folder}/{name}.ikg:", f"{folder}/start.ikg:")
    assert body["error"] == expected


@pytest.mark.parametrize("depth", [600, 100_000])
def test_json_nested_too_deep_is_400(server, depth):
    for path in ("/api/apply", "/api/parameter", "/api/control"):
        status, body = server.post(path, ("[" * depth + "]" * depth).encode(), raw=True)
        assert status == 400
        assert body["error"] == "the body is not valid JSON: arrays and objects nest deeper " \
                                "than 512 levels"


def test_a_tree_nested_deeper_than_the_limit_is_400(server):
    tree = {"tag": "module", "attrs": {"class": "Constant", "name": "C"}}
    for _ in range(150):
        tree = {"tag": "group", "attrs": {"name": "G"}, "children": [tree]}
    status, body = server.post("/api/apply", {"tree": tree})
    assert (status, body) == (400, {"error": '"tree": the tree is nested deeper than 100 '
                                             'levels'})


def test_a_body_over_the_limit_is_413(server):
    import http.client
    host, port = server.url.split("//")[1].split(":")
    conn = http.client.HTTPConnection(host, int(port), timeout=10)
    try:
        conn.putrequest("POST", "/api/apply")
        conn.putheader("Content-Type", "application/json")
        conn.putheader("Content-Length", str(5 << 20))
        conn.endheaders()                     # the body is refused before it is sent
        r = conn.getresponse()
        assert (r.status, json.load(r)) == (413, {
            "error": "the request body is larger than the limit of 4194304 bytes"})
    finally:
        conn.close()


def test_a_websocket_frame_nested_too_deep_gets_an_error_frame(server):
    from websockets.sync.client import connect
    with connect(server.url.replace("http", "ws") + "/api/ws",
                 origin=server.url) as ws:
        ws.send("[" * 100_000)
        assert _next(ws, "error") == {
            "type": "error", "error": "not valid JSON: arrays and objects nest deeper than "
                                      "512 levels"}
        ws.send(json.dumps({"type": "ping", "t": 1}))     # the connection stays open
        assert _next(ws, "pong") == {"type": "pong", "t": 1}


def test_a_refused_websocket_is_answered_403(server):
    from websockets.exceptions import InvalidStatus
    from websockets.sync.client import connect
    with pytest.raises(InvalidStatus) as refused:
        connect(server.url.replace("http", "ws") + "/api/ws", origin="http://evil.example")
    assert refused.value.response.status_code == 403


def _next(ws, kind):
    """The next text frame of a kind (status frames come in between)."""
    end = time.monotonic() + 10
    while time.monotonic() < end:
        frame = ws.recv(timeout=10)
        if isinstance(frame, str) and json.loads(frame).get("type") == kind:
            return json.loads(frame)
    raise AssertionError(f"no {kind} frame")


def test_a_build_that_never_returns_times_out_and_later_applies_go_on(folder, tmp_path):
    s = Server(folder, "--build-timeout", "1")
    try:
        marker = tmp_path / "looping"
        looping = {"tag": "group", "attrs": {"name": "L"}, "children": [
            {"tag": "module", "attrs": {"class": "LoopsInInit", "name": "L",
                                        "marker": str(marker)}}]}
        for _ in range(2):              # twice: the first stuck build refuses nothing
            start = time.monotonic()
            status, body = s.post("/api/apply", {"tree": looping})
            assert time.monotonic() - start < 5
            assert (status, body) == (422, {
                "error": "the build did not finish within 1 s (does a module's init or "
                         "configure never return?); it was abandoned",
                "node": None, "path": None})
        assert marker.exists()
        status, body = s.post("/api/open", {"filename": "start.ikg"})
        assert status == 200, body
        status, body = s.post("/api/apply", {"tree": _as_tree(os.path.join(folder,
                                                                            "start.ikg"))})
        assert status == 200, body
        start = time.monotonic()
        status, out, err = s.stop()
        assert time.monotonic() - start < 3
        assert status == 0
        assert "Traceback" not in err
        assert err.endswith("ikaros: leaving a build from the web UI that never returned\n")
    finally:
        if s.proc.poll() is None:
            s.proc.kill()
            s.proc.communicate()


def test_the_body_limit_is_set_on_the_command_line(folder):
    server = Server(folder, "--max-body", "2K")
    try:
        status, answer = server.post("/api/apply", b"[" + b" " * 3000 + b"]", raw=True)
        assert status == 413 and "2048 bytes" in answer["error"], answer
        status, _ = server.post("/api/control", {"state": "pause"})
        assert status == 200
    finally:
        server.stop()
