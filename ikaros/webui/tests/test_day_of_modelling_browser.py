"""What a user saw go wrong in a day of modelling (issue 27), in a real headless Chromium
against the real server. Each check failed before its fix; pixel checks read the widgets'
canvases. Screenshots go to a temporary folder."""
from __future__ import annotations

import os
import tempfile
import time

from browsing import ROOT, in_own_browser

EXAMPLES = os.path.join(ROOT, "examples")
REACHING = os.path.join(EXAMPLES, "planar_arm_reaching.ikg")
SHOTS = os.path.join(tempfile.gettempdir(), "ikaros-webui-shots")

# per plot of the main view: its x range and the coloured (series) pixels inside its
# plotting area; grid and text are grey, so a pixel with saturated colour is the data
PLOTS = """() => window.ikaros.mainView.widgets.filter((w) => w.xs !== undefined).map((w) => {
    const u = w.plot;
    if (!u) return {title: w.attrs.title, min: null, max: null, coloured: 0};
    const c = u.ctx.canvas, b = u.bbox;
    const d = u.ctx.getImageData(b.left, b.top, b.width, b.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) {
        const hi = Math.max(d[i], d[i + 1], d[i + 2]), lo = Math.min(d[i], d[i + 1], d[i + 2]);
        if (d[i + 3] > 100 && hi - lo > 60) n++;
    }
    return {title: w.attrs.title, min: u.scales.x.min, max: u.scales.x.max, coloured: n}; })"""


def shot(page, name):
    os.makedirs(SHOTS, exist_ok=True)
    page.screenshot(path=os.path.join(SHOTS, f"{name}.png"))


def wait_for(predicate, timeout=20.0, what="condition"):
    deadline = time.monotonic() + timeout
    while not (value := predicate()):
        if time.monotonic() > deadline:
            raise AssertionError(f"timed out waiting for {what}")
        time.sleep(0.05)
    return value


def show_view(page, group: str, index: int):
    page.click(f"#navigator a[data-group='{group}'][data-view='{index}']")
    page.wait_for_function(
        "([g, v]) => { const c = window.ikaros.built; return c && c.group === g && c.view === v; }",
        arg=[group, index])


def plots_drawn(page, tick: int, where: str):
    """Every plot of the view shows data ending at the paused tick (not at twice it)."""
    def drawn():
        plots = page.evaluate(PLOTS)
        ok = plots and all(p["coloured"] > 100 and p["max"] is not None
                           and tick - 20 <= p["max"] <= tick + 1 and p["max"] - p["min"] >= 40
                           for p in plots)
        return plots if ok else None
    try:
        wait_for(drawn, timeout=10, what=f"plots drawn {where}")
    except AssertionError:
        shot(page, f"blank-plots-{where}")
        raise AssertionError(f"{where}: plots at tick {tick}: {page.evaluate(PLOTS)}") from None


def test_plots_show_a_paused_model_on_every_way_a_view_opens():
    """Item 1: after a reload, a switch of views and leaving the editor, the plots of a paused
    model at tick > 0 show its data with the axis at the tick; after Open of another model
    the plots follow the new network's ticks."""
    def check(server, page):
        server.post("/api/control", {"state": "play"})
        wait_for(lambda: server.tick() > 1500, what="1500 ticks")
        server.post("/api/control", {"state": "pause"})
        tick = server.tick()
        page.reload()
        page.wait_for_function("() => window.ikaros && window.ikaros.socket.connected")
        plots_drawn(page, tick, "after-reload")
        show_view(page, "", 1)
        show_view(page, "", 0)
        plots_drawn(page, tick, "after-switching-views")
        page.click("#toggle-editor")
        page.wait_for_selector("#editor-host[data-ready] svg.network-view")
        page.click("#toggle-editor")
        page.wait_for_function("() => !document.querySelector('#editor-host[data-ready]')"
                               " || !window.ikaros.editor.active")
        plots_drawn(page, tick, "after-the-editor")

        # another model opened (from the editor's Open): its plots follow its own ticks
        server.post("/api/open", {"filename": "demo.ikg"})
        page.wait_for_function("() => window.ikaros.network && window.ikaros.network.name === 'Demo'")
        server.post("/api/control", {"state": "play"})
        wait_for(lambda: server.tick() > 600, what="600 ticks of the demo")
        server.post("/api/control", {"state": "pause"})
        now = server.tick()
        show_view(page, "", 0)
        plots_drawn(page, now, "after-open")
        shot(page, "plots-after-open")

    in_own_browser(REACHING, lambda s, p: None, check)


def test_system_inspector_says_what_its_figures_are():
    """Item 4: "actual duration" is the mean over the last second (the tick rate's inverse)
    with the last tick's beside it, labelled; CPU usage says of how many cores."""
    def check(server, page):
        server.post("/api/control", {"state": "play"})
        wait_for(lambda: server.tick() > 500, what="500 ticks")
        time.sleep(1.5)                               # a whole window of playing
        t0, n0 = time.monotonic(), server.tick()
        time.sleep(1.0)
        real = (time.monotonic() - t0) / (server.tick() - n0) * 1000   # ms per tick
        page.wait_for_function("() => document.querySelector('#sys-actual_tick_duration_mean')"
                               ".textContent.endsWith(' ms')")
        labels = page.evaluate("""() => [...document.querySelectorAll('#system-inspector tr')]
            .filter((r) => r.querySelector('#sys-actual_tick_duration, #sys-actual_tick_duration_mean'))
            .map((r) => r.cells[0].textContent)""")
        assert labels == ["actual duration (1 s mean)",
                          "actual duration (last tick)"], labels
        mean = float(page.inner_text("#sys-actual_tick_duration_mean").split()[0])
        rate = float(page.inner_text("#sys-ticks_per_second"))
        assert abs(mean - 1000 / rate) <= 0.01 + 0.002 * mean, (mean, rate)
        assert 0.5 * real < mean < 2 * real, (mean, real)
        usage = page.inner_text("#sys-cpu_usage")
        cores = os.cpu_count()
        assert f" of {cores} {'core' if cores == 1 else 'cores'} (" in usage, usage
        share = float(usage.split()[0]) / 100
        busy = float(usage.split("(")[1].split()[0])
        assert abs(busy - share * cores) <= 0.01 + 0.001 * cores, usage
        shot(page, "system-inspector")

    in_own_browser(REACHING, lambda s, p: None, check)
