"""What the browser tests share: Debian's Chromium driven by Playwright, and the real
``ikaros`` server started on a free 127.0.0.1 port with a bounded wait."""
from __future__ import annotations

import json
import os
import socket
import subprocess
import sys
import threading
import time
import urllib.request

import pytest

CHROMIUM = "/usr/bin/chromium"
ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
        "--disable-background-networking", "--disable-component-update", "--disable-sync"]
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))))
ARTIFACTS = os.path.join(ROOT, "test-artifacts")
TIMEOUT = 15_000   # ms, for waits in the page

# the axe-core accessibility audit (vendored): add AXE to a page with add_script_tag, then
# page.evaluate(SERIOUS) lists the serious and critical violations of the whole page
AXE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "vendor", "axe-core", "axe.min.js")
SERIOUS = """async () => (await axe.run(document, {resultTypes: ['violations']})).violations
    .filter((v) => v.impact === 'serious' || v.impact === 'critical')
    .map((v) => `${v.id}: ${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(', ')}`)"""

if not os.path.exists(CHROMIUM):
    raise RuntimeError(f"the browser tests need Debian's Chromium at {CHROMIUM}: "
                       f"`bash scripts/test.sh` installs it (apt-get install chromium)")

from playwright import sync_api  # noqa: E402,F401  (re-exported for the tests)


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Server:
    """``python -m ikaros -w PORT [OPTIONS] MODEL`` on 127.0.0.1, with JSON helpers for its
    API (``options=["--replay"]`` with a recording for MODEL serves a replay)."""

    def __init__(self, model: str, start_within: float = 30, options: tuple = ()):
        self.port = free_port()
        self.base = f"http://127.0.0.1:{self.port}"
        self.proc = subprocess.Popen([sys.executable, "-m", "ikaros", "-w", str(self.port),
                                      *options, model], cwd=ROOT, stdout=subprocess.PIPE,
                                     stderr=subprocess.STDOUT)
        deadline = time.monotonic() + start_within
        while True:
            try:
                self.get("/api/status")
                return
            except OSError:
                if self.proc.poll() is not None or time.monotonic() > deadline:
                    self.stop()
                    out = self.proc.stdout.read().decode(errors="replace")
                    pytest.fail(f"the server did not start for {model}:\n{out}")
                time.sleep(0.1)

    def stop(self) -> None:
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(10)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()

    def get(self, path: str):
        with urllib.request.urlopen(self.base + path, timeout=10) as r:
            return json.loads(r.read())

    def post(self, path: str, body: dict):
        req = urllib.request.Request(self.base + path, data=json.dumps(body).encode(),
                                     headers={"Content-Type": "application/json"})
        with urllib.request.urlopen(req, timeout=10) as r:
            return json.loads(r.read())

    def data(self, *paths: str) -> dict:
        return self.get("/api/data?paths=" + ",".join(paths))

    def parameter(self, path: str):
        module, _, name = path.rpartition(".")
        info = self.get("/api/module?path=" + module)
        return next(p["value"] for p in info["parameters"] if p["name"] == name)

    def tick(self) -> int:
        return self.get("/api/status")["tick"]

    def step(self, n: int) -> int:
        """n ticks through POST /api/control, one at a time; the tick count afterwards."""
        tick = self.tick()
        for _ in range(n):
            self.post("/api/control", {"state": "step"})
            deadline = time.monotonic() + 20
            while (now := self.tick()) < tick + 1:
                assert time.monotonic() < deadline, "the step did not run"
                time.sleep(0.01)
            tick = now
        return tick


def in_own_browser(model: str, open_page, check, options: tuple = ()) -> None:
    """Serve a model (with the command-line ``options`` of :class:`Server`), open the app in
    Chromium, then run ``open_page(server, page)`` and ``check(server, page)``. The browser runs in a thread of its own, with its own
    Playwright: the sync API cannot start inside another module's running Playwright
    (test_browser.py keeps one for the whole session)."""
    os.makedirs(ARTIFACTS, exist_ok=True)
    server = Server(model, options=options)
    failure = []

    def run():
        try:
            with sync_api.sync_playwright() as p:
                browser = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
                try:
                    page = browser.new_page(viewport={"width": 1400, "height": 900})
                    errors = []
                    page.on("pageerror", lambda e: errors.append(str(e)))
                    page.errors = errors
                    page.set_default_timeout(TIMEOUT)
                    page.goto(server.base + "/")
                    page.wait_for_function(
                        "() => window.ikaros && window.ikaros.socket.connected")
                    open_page(server, page)
                    check(server, page)
                finally:
                    browser.close()
        except BaseException as e:      # noqa: BLE001 - handed to the test's thread
            failure.append(e)

    try:
        thread = threading.Thread(target=run, daemon=True)
        thread.start()
        thread.join(240)
        if thread.is_alive():
            pytest.fail("the browser part did not finish in 240 s")
    finally:
        server.stop()
    if failure:
        raise failure[0]
