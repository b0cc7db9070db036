"""Time plots in a real headless Chromium (issue 37). At 300 x 60, 120 x 120 and 100 x 80 a
plot drops what of its axes does not fit, but no text is drawn over the plotting area or
outside the canvas, and every value plotted lies inside the plotting area (screenshot:
test-artifacts/plot-sizes.png). After a reload a plot shows the samples it showed before,
up to the current tick."""
from __future__ import annotations

import os
import time

import pytest

from browsing import ARTIFACTS, in_own_browser

pytestmark = pytest.mark.slow

MODEL = """<?xml version="1.0"?>
<group name="P">
    <module class="FunctionGenerator" name="Square" type="square" frequency="0.1" amplitude="1" />
    <view name="Plots">
        <plot source="Square.OUTPUT" title="wide" x="20" y="20" width="300" height="60" />
        <plot source="Square.OUTPUT" title="square" x="20" y="100" width="120" height="120" />
        <plot source="Square.OUTPUT" title="tiny" x="160" y="100" width="100" height="80" />
        <plot source="Square.OUTPUT" title="fixed" x="160" y="200" width="100" height="80" min="-1" max="1" />
        <plot source="Square.OUTPUT" title="big" x="340" y="20" width="400" height="250" unit="volt" />
    </view>
</group>
"""

# every text drawn on a canvas, with its box in canvas pixels (the font is 10 px; rotated
# texts, an axis title, give their centre only)
RECORD = """() => {
    const fill = CanvasRenderingContext2D.prototype.fillText;
    CanvasRenderingContext2D.prototype.fillText = function (text, x, y, ...rest) {
        const t = this.getTransform(), w = this.measureText(String(text)).width * t.a;
        const px = t.a * x + t.c * y + t.e, py = t.b * x + t.d * y + t.f, h = 10 * t.d;
        const left = {left: px, start: px, center: px - w / 2, right: px - w, end: px - w}[this.textAlign];
        const top = {top: py, hanging: py, middle: py - h / 2, bottom: py - h,
                     alphabetic: py - 0.8 * h, ideographic: py - h}[this.textBaseline];
        (this.canvas.texts ||= []).push({text: String(text), left, top, right: left + w,
                                         bottom: top + h, rotated: t.b !== 0});
        return fill.call(this, text, x, y, ...rest);
    };
}"""

DRAWN = """async (title) => {
    const w = window.ikaros.mainView.widgets.find((w) => w.el.dataset.title === title);
    const u = w.plot, c = u.ctx.canvas;
    c.texts = [];
    u.redraw(false, true);
    await new Promise((done) => requestAnimationFrame(() => setTimeout(done, 0)));
    const b = u.bbox;
    const ys = [];
    for (const s of w.lo.concat(w.hi)) for (const v of s) ys.push(u.valToPos(v, 'y', true));
    return {texts: c.texts, width: c.width, height: c.height, ratio: c.width / u.width,
            box: {left: b.left, top: b.top, right: b.left + b.width, bottom: b.top + b.height},
            ys, samples: w.xs.length};
}"""


def test_small_plots_drop_what_does_not_fit_and_never_draw_over_the_data(tmp_path):
    model = tmp_path / "plots.ikg"
    model.write_text(MODEL)

    def open_page(server, page):
        page.add_init_script(script=f"({RECORD})()")
        page.reload()
        page.wait_for_function("() => window.ikaros && window.ikaros.socket.connected")
        server.step(40)
        page.wait_for_function("() => window.ikaros.mainView.widgets.every((w) => "
                               "w.plot && w.xs.length >= 40)")

    def check(server, page):
        seen = {}
        for title in ("wide", "square", "tiny", "fixed", "big"):
            d = page.evaluate(DRAWN, title)
            box, r = d["box"], d["ratio"]
            assert box["right"] - box["left"] >= 40 * r and box["bottom"] - box["top"] >= 20 * r, \
                (title, box)
            for t in d["texts"]:
                if t["rotated"]:
                    continue
                assert t["left"] >= -1 and t["right"] <= d["width"] + 1 and t["top"] >= -1 \
                    and t["bottom"] <= d["height"] + 1, (title, "outside the canvas", t)
                overlap = (min(t["right"], box["right"]) - max(t["left"], box["left"]) > 0.5 and
                           min(t["bottom"], box["bottom"]) - max(t["top"], box["top"]) > 0.5)
                assert not overlap, (title, "drawn over the plotting area", t, box)
            assert d["ys"] and all(box["top"] <= y <= box["bottom"] for y in d["ys"]), \
                (title, "a value outside the plotting area", box, min(d["ys"]), max(d["ys"]))
            below = [t["text"] for t in d["texts"] if t["top"] >= box["bottom"]]
            beside = [t["text"] for t in d["texts"] if t["right"] <= box["left"]]
            seen[title] = (below, beside)
        numbers = lambda texts: [t for t in texts if t.replace(",", "").replace("-", "").replace(".", "").isdigit()]
        for title in ("square", "tiny", "fixed", "big"):
            below, beside = seen[title]
            assert numbers(below), (title, "no x tick values", below)
            assert len(numbers(beside)) >= 2, (title, "no y tick values", beside)
        assert "tick" in seen["square"][0] and "tick" in seen["big"][0]
        assert len(numbers(seen["wide"][1])) >= 2, seen["wide"]
        page.screenshot(path=os.path.join(ARTIFACTS, "plot-sizes.png"),
                        clip={"x": 215, "y": 30, "width": 780, "height": 320})
        assert not page.errors, page.errors

    in_own_browser(str(model), open_page, check)


HISTORY = """<?xml version="1.0"?>
<group name="H" tick_duration="0.001">
    <module class="FunctionGenerator" name="Square" type="square" frequency="0.05" amplitude="1" />
    <module class="FunctionGenerator" name="Sine" frequency="0.01" />
    <view name="Plots">
        <plot source="Square.OUTPUT" title="square" x="20" y="20" width="200" height="120" />
        <plot source="Sine.OUTPUT" title="sine" x="240" y="20" width="400" height="200" />
    </view>
</group>
"""

SAMPLES = """() => Object.fromEntries(window.ikaros.mainView.widgets.map((w) =>
    [w.el.dataset.title, {xs: w.xs.slice(), hi: w.hi[0].slice(), lo: w.lo[0].slice()}]))"""


def _settled(page, tick):
    """The plots' samples once both have their history (not only the value read when the
    page opened) and end at ``tick``."""
    page.wait_for_function("(t) => window.ikaros.mainView.widgets.every((w) => "
                           "w.seenHistory && w.xs.length && w.xs[w.xs.length - 1] === t)", arg=tick)
    return page.evaluate(SAMPLES)


def test_after_a_reload_plots_show_the_samples_they_showed_up_to_the_current_tick(tmp_path):
    model = tmp_path / "history.ikg"
    model.write_text(HISTORY)

    def check(server, page):
        # 30 steps of a model paused at tick 0: tick 0 (the value init wrote) stays
        server.step(30)
        before = _settled(page, 30)
        assert before["square"]["xs"] == list(range(31)), before["square"]["xs"]
        page.reload()
        page.wait_for_function("() => window.ikaros && window.ikaros.socket.connected")
        assert _settled(page, 30) == before
        # played as fast as it goes, then paused: every tick the plot is wide, as before
        server.post("/api/control", {"state": "play"})
        deadline = time.monotonic() + 20
        while server.tick() < 3000:
            assert time.monotonic() < deadline, "the model did not run"
            time.sleep(0.05)
        server.post("/api/control", {"state": "pause"})
        deadline = time.monotonic() + 10
        while server.get("/api/status")["state"] != "pause":
            assert time.monotonic() < deadline, "the model did not pause"
            time.sleep(0.05)
        tick = server.tick()
        before = _settled(page, tick)
        for title, width in (("square", 198), ("sine", 398)):
            xs = before[title]["xs"]
            assert xs == list(range(tick - len(xs) + 1, tick + 1)) and len(xs) >= width - 2, \
                (title, len(xs), xs[:3], xs[-3:])
        page.reload()
        page.wait_for_function("() => window.ikaros && window.ikaros.socket.connected")
        after = _settled(page, tick)
        assert after == before
        assert not page.errors, page.errors

    in_own_browser(str(model), lambda server, page: None, check)
