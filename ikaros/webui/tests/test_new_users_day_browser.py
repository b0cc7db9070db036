"""A new user's day in a real headless Chromium (issue 37): build a model in the editor,
Apply, run, watch its plot, change the model and Apply again, record, reload. After each
Apply every module still follows its inputs (before the fix Add kept adding the inputs of
the network Apply had replaced: its plot went flat), and the reloaded plot shows what it
showed. Screenshots go to test-artifacts/."""
from __future__ import annotations

import os
import shutil
import time

import pytest

from browsing import ARTIFACTS, ROOT, in_own_browser
from test_editor_browser import add_module, answer, connect

pytestmark = pytest.mark.slow

START = os.path.join(ROOT, "examples", "modules", "Add_example.ikg")

SAMPLES = """() => { const w = window.ikaros.mainView.widgets.find((w) => w.xs !== undefined);
    return w ? {xs: w.xs.slice(), hi: w.hi[0].slice()} : null; }"""


# the last tick a plot shows from its history (not the value read when the page opened)
LAST = """() => { const w = window.ikaros.mainView.widgets.find((w) => w.xs !== undefined);
    return w && w.seenHistory && w.xs.length ? w.xs[w.xs.length - 1] : null; }"""


def values(server, *paths):
    data = server.data(*paths)["data"]
    return [data[p][0] for p in paths]


def follows(server):
    """One step: Add's output is the sum of the generators' values of the tick before."""
    a, b = values(server, "FunctionGenerator.OUTPUT", "FunctionGenerator2.OUTPUT")
    server.step(1)
    (total,) = values(server, "Add.OUTPUT")
    assert total == pytest.approx(a + b, abs=1e-6), (a, b, total)


def play(server, page, ticks):
    start = server.tick()
    server.post("/api/control", {"state": "realtime"})
    deadline = time.monotonic() + 30
    while server.tick() < start + ticks:
        assert time.monotonic() < deadline, "the model does not run"
        time.sleep(0.05)
    server.post("/api/control", {"state": "pause"})
    deadline = time.monotonic() + 15
    while True:             # paused, and the plot has the last tick the server ran
        tick = server.tick()
        last = page.evaluate(LAST)
        if server.get("/api/status")["state"] == "pause" and last == tick == server.tick():
            return tick
        assert time.monotonic() < deadline, (tick, last)
        time.sleep(0.1)

def test_a_day_of_modelling_leaves_no_module_frozen(tmp_path):
    shutil.copy(START, tmp_path / "start.ikg")
    data = tmp_path / "data"

    def check(server, page):
        page.click("#toggle-editor")
        page.wait_for_selector("#editor-host[data-ready] svg.network-view")
        page.click("#ed-new")
        answer(page, "#new-name", "Day")
        page.wait_for_function("() => document.querySelectorAll('#editor-host rect.box').length === 0")
        add_module(page, "FunctionGenerator")
        add_module(page, "FunctionGenerator")
        page.wait_for_selector("#editor-host rect.box[data-name='FunctionGenerator2']")
        add_module(page, "Add")
        connect(page, "FunctionGenerator", "OUTPUT", "Add", "INPUT1")
        connect(page, "FunctionGenerator2", "OUTPUT", "Add", "INPUT2")
        page.click("#ed-add-view")
        answer(page, "#dialog-input", "Main")
        page.wait_for_selector(".editor-tab.view-tab.current")
        page.select_option("#ed-add-widget", "plot")
        page.wait_for_selector("#editor-host .widget-frame[data-widget='plot']")
        page.select_option("#editor-inspector select[data-attr='source']", "Add.OUTPUT")
        page.click(".editor-tab[data-mode='network']")
        page.click("#ed-apply")
        page.wait_for_function("() => document.querySelector('#editor-status').dataset.level === 'ok'")
        server.step(5)
        follows(server)

        # a second module after Add, and Apply: Add is kept, and still adds
        add_module(page, "Scale")
        connect(page, "Add", "OUTPUT", "Scale", "INPUT")
        page.click("#ed-apply")
        page.wait_for_function("() => document.querySelector('#editor-status').textContent.includes('kept')")
        follows(server)
        page.click("#toggle-editor")
        page.wait_for_selector("#editor-host", state="hidden")
        tick = play(server, page, 40)
        plot = page.evaluate(SAMPLES)
        after = [v for x, v in zip(plot["xs"], plot["hi"]) if x > tick - 30]
        assert max(after) - min(after) > 0.1, after          # not flat
        page.screenshot(path=os.path.join(ARTIFACTS, "day-plot.png"))

        # record a few ticks of Add and the generators, then reload
        page.click("#run-record")
        page.fill("#record-only", "Add.*, FunctionGenerator*")
        page.wait_for_selector("#record-amount:has-text('3 outputs, 3 values')")
        page.click("#record-start")
        page.wait_for_selector("#run-record.active")
        tick = play(server, page, 20)
        page.click("#run-record")
        page.wait_for_selector("#run-record:not(.active)")
        before = page.evaluate(SAMPLES)
        page.reload()
        page.wait_for_function("() => window.ikaros && window.ikaros.socket.connected")
        page.wait_for_function(f"(t) => ({LAST})() === t", arg=tick)
        assert page.evaluate(SAMPLES) == before
        follows(server)
        assert not page.errors, page.errors

    in_own_browser(str(tmp_path / "start.ikg"), lambda s, p: None, check, options=["-u", str(data)])
    assert len([f for f in os.listdir(data) if f.endswith(".h5")]) == 1
