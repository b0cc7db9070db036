"""The HTTP-script harness of the kernel-test runner (reference TESTS.md §2.1).

A model with an ``http_requests`` attribute is run as a real ``ikaros`` process serving the
web UI on 127.0.0.1 (a free port, ``-w 0``; ``-r`` unless ``http_real_time="false"``). The
runner waits for ``http_ready_path`` (default ``/api/network``) to answer, performs the
``||``-separated actions in order, and always stops the process at the end (SIGTERM, then a
kill). The caller checks the exit status and the output as for batch models.

Actions (``${TEST_DIR}`` and ``${TMP}`` are expanded in each):

* ``/path``: a GET that must answer 2xx;
* ``sleep:S``;
* ``wait_contains:/path:text``: GET until the answer contains text;
* ``wait_output:text`` / ``wait_output_count:N:text``: wait until the process has printed
  text (N times);
* ``post_json:/path:JSON`` and ``post_json_file:/path:file``: a POST that must answer 2xx
  (our API changes things with POST where Ikaros 3 uses GET or ``put_json_file``);
* ``post_json_expect:/path:CODE:JSON``: a POST that must answer CODE;
* ``assert_contains:/path:text`` / ``assert_not_contains:/path:text``;
* ``assert_status:/path:CODE``: a GET that must answer CODE;
* ``assert_json_field:/path:field:JSON``: the field (dotted, list items by index, or a JSON
  pointer ``/data/A.OUTPUT``) of the JSON answer equals the JSON value;
* ``assert_posted_field:field:JSON``: the same for the answer to the last POST;
* ``assert_unchanged:/path:field:S``: the field is the same S seconds later;
* ``assert_same_bytes:/path:file``: a GET answers the file's bytes;
* ``assert_snapshot_tick:BUFFER``: ``/api/data`` of a buffer that counts the ticks
  completed gives a value equal to the answer's tick, five times while the model runs;
* ``assert_min_duration:S:/path:JSON``: a POST that takes at least S seconds;
* ``probe:NAME``: an HTTP-framing probe on raw sockets (http_probes.py);
* ``ws_first_frame``, ``ws_coherent``, ``ws_max_frames``, ``ws_open``, ``ws_log_count``:
  WebSocket clients
  (http_websocket.py).

With ``http_occupy_port="true"`` the runner holds a listening socket on a free port and
passes that port with ``-w``; no actions run (the server must fail to start).

A failed action ends the script; its message is one of the unmet expectations.
"""
from __future__ import annotations

import json
import os
import re
import signal
import socket
import subprocess
import sys
import threading
import time

import httpx

import http_websocket
from http_probes import PROBES, ScriptFailure

READY_TIMEOUT = 15.0       # seconds for the server to start and answer
WAIT_TIMEOUT = 10.0        # seconds for a wait_* action
STOP_TIMEOUT = 8.0         # seconds from SIGTERM to a kill
REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


class Process:
    """An ``ikaros`` process whose merged output is collected as it comes."""

    def __init__(self, argv: list[str], cwd: str):
        env = dict(os.environ, PYTHONPATH=REPO + os.pathsep + os.environ.get("PYTHONPATH", ""),
                   PYTHONUNBUFFERED="1")
        self.proc = subprocess.Popen([sys.executable, "-m", "ikaros"] + argv, cwd=cwd, env=env,
                                     stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                     stderr=subprocess.STDOUT, text=True, errors="replace")
        self._chunks: list[str] = []
        self._terminated = False
        self._lock = threading.Lock()
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self):
        for line in self.proc.stdout:
            with self._lock:
                self._chunks.append(line)

    @property
    def output(self) -> str:
        with self._lock:
            return "".join(self._chunks)

    def wait_for(self, found, timeout: float, what: str):
        """Waits until found(output) is true; the process ending first is a failure."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if found(self.output):
                return
            if self.proc.poll() is not None:
                self._reader.join(2)
                if found(self.output):
                    return
                raise ScriptFailure(f"the process ended (status {self.proc.returncode}) "
                                    f"before {what}")
            time.sleep(0.02)
        raise ScriptFailure(f"timed out after {timeout:g} s waiting for {what}")

    def terminate(self):
        """SIGTERM, once (a second one would end the process at once)."""
        if not self._terminated and self.proc.poll() is None:
            self._terminated = True
            self.proc.send_signal(signal.SIGTERM)

    def stop(self) -> int:
        """SIGTERM, then a kill if it has not ended; returns the exit status."""
        if self.proc.poll() is None:
            self.terminate()
            try:
                self.proc.wait(STOP_TIMEOUT)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        self._reader.join(5)
        self.proc.stdout.close()
        return self.proc.returncode


def _json_at(value, field: str):
    """The field of a JSON value: dotted (``top.modules.0``), or a JSON pointer
    (``/data/A.OUTPUT``) for keys that hold dots."""
    keys = field[1:].split("/") if field.startswith("/") else field.split(".") if field else []
    for key in keys:
        value = value[int(key)] if isinstance(value, list) else value[key]
    return value


class Script:
    """Performs the actions against the server at base (``http://127.0.0.1:PORT``)."""

    def __init__(self, process: Process, base: str):
        self.process, self.base = process, base
        self.client = httpx.Client(base_url=base, timeout=10.0)
        self.log_clients = http_websocket.LogClients()
        self.last: httpx.Response | None = None       # the answer to the last POST

    def close(self):
        self.client.close()
        self.log_clients.close()

    def get(self, path: str) -> httpx.Response:
        return self.client.get(path)

    def post(self, path: str, body) -> httpx.Response:
        self.last = self.client.post(path, json=body)
        return self.last

    def field(self, answer: httpx.Response, field: str, action: str):
        try:
            return _json_at(answer.json(), field)
        except (ValueError, KeyError, IndexError, TypeError):
            raise ScriptFailure(f"{action}: no field {field} in {answer.text[:400]}")

    def run(self, action: str):
        kind, _, rest = action.partition(":")
        if action.startswith("/"):
            self._expect(self.get(action), 200, action)
        elif kind == "sleep":
            time.sleep(float(rest))
        elif kind == "wait_contains":
            path, _, text = rest.partition(":")
            self.poll(lambda: text in self.get(path).text, f"{text!r} in {path}")
        elif kind == "wait_output":
            self.process.wait_for(lambda out: rest in out, WAIT_TIMEOUT, repr(rest))
        elif kind == "wait_output_count":
            count, _, text = rest.partition(":")
            self.process.wait_for(lambda out: out.count(text) >= int(count), WAIT_TIMEOUT,
                                  f"{text!r} {count} times")
        elif kind == "post_json":
            path, _, body = rest.partition(":")
            self._expect(self.post(path, json.loads(body)), 200, action)
        elif kind == "post_json_file":
            path, _, file = rest.partition(":")
            with open(file, encoding="utf-8") as f:
                self._expect(self.post(path, json.load(f)), 200, action)
        elif kind == "post_json_expect":
            path, code, body = rest.split(":", 2)
            self._expect(self.post(path, json.loads(body)), int(code), action)
        elif kind in ("assert_contains", "assert_not_contains"):
            path, _, text = rest.partition(":")
            body = self.get(path).text
            if (text in body) != (kind == "assert_contains"):
                raise ScriptFailure(f"{action}: the answer was {body[:400]}")
        elif kind == "assert_status":
            path, _, code = rest.rpartition(":")
            self._expect(self.get(path), int(code), action)
        elif kind in ("assert_json_field", "assert_posted_field"):
            if kind == "assert_json_field":
                path, field, expected = rest.split(":", 2)
                answer = self.get(path)
            else:
                (field, expected), answer = rest.split(":", 1), self.last
                if answer is None:
                    raise ScriptFailure(f"{action}: no POST before it")
            found = self.field(answer, field, action)
            if found != json.loads(expected):
                raise ScriptFailure(f"{action}: {field} is {found!r}")
        elif kind == "assert_unchanged":
            path, field, seconds = rest.split(":", 2)
            before = self.field(self.get(path), field, action)
            time.sleep(float(seconds))
            after = self.field(self.get(path), field, action)
            if after != before:
                raise ScriptFailure(f"{action}: {field} went from {before!r} to {after!r}")
        elif kind == "assert_same_bytes":
            path, _, file = rest.partition(":")
            with open(file, "rb") as f:
                expected = f.read()
            answer = self.get(path)
            self._expect(answer, 200, action)
            if answer.content != expected:
                raise ScriptFailure(f"{action}: {len(answer.content)} bytes differ from the "
                                    f"file's {len(expected)}")
        elif kind == "assert_snapshot_tick":
            self._snapshot_tick(rest)
        elif kind == "assert_min_duration":
            seconds, path, body = rest.split(":", 2)
            start = time.monotonic()
            self._expect(self.post(path, json.loads(body)), 200, action)
            took = time.monotonic() - start
            if took < float(seconds):
                raise ScriptFailure(f"{action}: took only {took:.3f} s")
        elif kind == "ws_first_frame":
            http_websocket.first_frame(self.base, *rest.split(":"))
        elif kind == "ws_coherent":
            http_websocket.coherent(self.base, *rest.split(":"))
        elif kind == "ws_max_frames":
            http_websocket.max_frames(self.base, *rest.split(":"))
        elif kind == "ws_open":
            self.log_clients.open(self.base, int(rest))
        elif kind == "ws_log_count":
            text, _, count = rest.rpartition(":")
            self.log_clients.count(text, int(count))
        elif kind == "probe":
            if rest not in PROBES:
                raise ScriptFailure(f"no probe named {rest!r}")
            PROBES[rest](self.base)
        else:
            raise ScriptFailure(f"unknown action {action!r}")

    @staticmethod
    def _expect(answer: httpx.Response, code: int, action: str):
        ok = 200 <= answer.status_code < 300 if code == 200 else answer.status_code == code
        if not ok:
            raise ScriptFailure(f"{action}: status {answer.status_code}: {answer.text[:400]}")

    @staticmethod
    def poll(found, what: str):
        """Waits until found() is true (a refused connection counts as false)."""
        deadline = time.monotonic() + WAIT_TIMEOUT
        while time.monotonic() < deadline:
            try:
                if found():
                    return
            except httpx.TransportError:
                pass
            time.sleep(0.05)
        raise ScriptFailure(f"timed out waiting for {what}")

    def _snapshot_tick(self, buffer: str):
        ticks = set()
        for _ in range(5):
            answer = self.get(f"/api/data?paths={buffer}").json()
            value = answer["data"][buffer]
            value = value[0] if isinstance(value, list) else value
            if value != answer["tick"]:
                raise ScriptFailure(f"{buffer} is {value} at tick {answer['tick']}")
            ticks.add(answer["tick"])
            time.sleep(0.05)
        if len(ticks) < 2:
            raise ScriptFailure(f"the model did not run: tick {ticks}")


def run(path: str, attrs: dict, cli_args: list[str], expand,
        tmp_path) -> tuple[int, str, list[str]]:
    """Runs the model at path (root attributes ``attrs``) with its HTTP script, cli_args
    before the file; (exit status, output, failures)."""
    argv = ["-w", "0"]
    if attrs.get("http_real_time", "true") != "false":
        argv.append("-r")
    occupied = None
    if attrs.get("http_occupy_port") == "true":
        occupied = socket.socket()
        occupied.bind(("127.0.0.1", 0))
        occupied.listen(1)
        argv = ["-w", str(occupied.getsockname()[1])]
    argv += [expand(a) for a in cli_args] + [path]
    failures = []
    process = Process(argv, str(tmp_path))
    try:
        if occupied is not None:
            process.proc.wait(READY_TIMEOUT)
        else:
            _script(process, attrs, expand)
    except (ScriptFailure, httpx.HTTPError, OSError, subprocess.TimeoutExpired,
            http_websocket.WebSocketException, TimeoutError) as e:
        failures.append(f"HTTP script: {type(e).__name__}: {e}")
    finally:
        code = process.stop()
        if occupied is not None:
            occupied.close()
    return code, process.output, failures


def _script(process: Process, attrs: dict, expand):
    process.wait_for(lambda out: re.search(r"serving .* at http://127\.0\.0\.1:\d+/", out),
                     READY_TIMEOUT, "the server to start")
    base = re.search(r"at (http://127\.0\.0\.1:\d+)/", process.output).group(1)
    script = Script(process, base)
    ready = attrs.get("http_ready_path", "/api/network")
    script.poll(lambda: script.get(ready).status_code == 200, f"{ready} to answer")
    try:
        for action in attrs["http_requests"].split("||"):
            if action.strip():
                script.run(expand(action.strip()))
    finally:
        script.close()              # an open connection delays the server's shutdown
    if attrs.get("http_terminate_after_requests") == "true":
        process.terminate()
