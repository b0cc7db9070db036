"""What a user saw go wrong in a day of modelling (issue 27), in a real headless Chromium
against the real server. Each check failed before its fix; pixel checks read the widgets'
canvases. Screenshots go to a temporary folder."""
from __future__ import annotations

import os
import re
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


# The bottom-left corner of a plot drawn with the x axis's tick labels alone and with the y
# axis's alone, ticks 3000..3100 (a label at the left end) and values -1..1: the box of the
# text's ink (dark grey; the series' colour and the light grid are left out) in each.
LABEL_INK = """async () => {
    const w = window.ikaros.mainView.widgets.find((v) => v.xs !== undefined);
    w.xs = Array.from({length: 101}, (_, i) => 3000 + i);
    w.lo = w.sel.map(() => w.xs.map((t) => Math.sin(t / 8)));
    w.hi = w.lo.map((a) => a.slice());
    const uPlot = (await import("/static/vendor/uplot/uPlot.esm.js")).default;
    const ink = async (only) => {
        const o = w.options(w.plot.width, w.plot.height);
        const blank = (u, vals) => vals.map(() => "");
        o.axes[only === "x" ? 1 : 0].values = blank;
        o.axes[0].label = undefined;
        const div = document.createElement("div");
        document.body.appendChild(div);
        const u = new uPlot(o, w.data(), div);
        await new Promise((r) => setTimeout(r, 100));      // uPlot draws in a microtask
        const b = u.bbox, c = u.ctx;
        const x0 = 0, y0 = Math.max(0, b.top + b.height - 24), x1 = b.left + 40, y1 = b.top + b.height + 26;
        const d = c.getImageData(x0, y0, x1 - x0, y1 - y0).data;
        let box = null;
        for (let j = 0; j < y1 - y0; j++) for (let i = 0; i < x1 - x0; i++) {
            const k = 4 * (j * (x1 - x0) + i);
            const hi = Math.max(d[k], d[k + 1], d[k + 2]), lo = Math.min(d[k], d[k + 1], d[k + 2]);
            if (d[k + 3] > 128 && hi < 150 && hi - lo < 40) {
                const X = x0 + i, Y = y0 + j;
                box = box ? {x0: Math.min(box.x0, X), y0: Math.min(box.y0, Y), x1: Math.max(box.x1, X), y1: Math.max(box.y1, Y)}
                          : {x0: X, y0: Y, x1: X, y1: Y};
            }
        }
        u.destroy();
        div.remove();
        return box;
    };
    return {x: await ink("x"), y: await ink("y")};
}"""


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
        # item 7: after Fit the delay-1 feedback line (around every box) stays in the pane
        page.click("#ed-fit")
        time.sleep(0.3)
        inside_pane(page, "the reaching model after Fit")
        page.click("#toggle-editor")
        page.wait_for_function("() => !document.querySelector('#editor-host[data-ready]')"
                               " || !window.ikaros.editor.active")
        plots_drawn(page, tick, "after-the-editor")

        # another model opened (from the editor's Open): its plots follow its own ticks
        server.post("/api/open", {"filename": "demo.ikg"})
        page.wait_for_function("() => window.ikaros.network && window.ikaros.network.name === 'Demo'"
                               " && window.ikaros.built && window.ikaros.socket.subscriptions"
                               ".some((s) => s.path === 'Mix.OUTPUT')")
        server.post("/api/control", {"state": "play"})
        wait_for(lambda: server.tick() > 600, what="600 ticks of the demo")
        server.post("/api/control", {"state": "pause"})
        now = server.tick()
        show_view(page, "", 0)
        plots_drawn(page, now, "after-open")
        shot(page, "plots-after-open")

        # item 7: the demo's plot (range -1..1): its lowest y label "-1" and the x tick
        # labels, drawn alone, have ink boxes at least 4 pixels apart (they touched)
        ink = page.evaluate(LABEL_INK)
        y, x = ink["y"], ink["x"]
        assert y and x, ink
        gap = 4
        apart = (y["x1"] + gap <= x["x0"] or x["x1"] + gap <= y["x0"] or
                 y["y1"] + gap <= x["y0"] or x["y1"] + gap <= y["y0"])
        assert apart, f"the y label -1 {y} meets the x tick labels {x}"

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


# --- the editor ---------------------------------------------------------------------------

BOXES = """() => [...document.querySelectorAll('#editor-host svg rect.box')].map((r) => {
    const b = r.getBoundingClientRect();
    return {name: r.dataset.name, kind: r.dataset.kind, x: b.x, y: b.y, w: b.width, h: b.height};
})"""
# every connection's line and the pane it is drawn in, on screen
LINES = """() => ({pane: document.querySelector('#editor-host svg.network-view').getBoundingClientRect().toJSON(),
    lines: [...document.querySelectorAll('#editor-host svg g.edge path.edge-line')].map((p) => {
        const b = p.getBoundingClientRect();
        return {source: p.parentNode.dataset.source, target: p.parentNode.dataset.target,
                x0: b.left, y0: b.top, x1: b.right, y1: b.bottom}; })})"""


def open_editor(server, page):
    page.click("#toggle-editor")
    page.wait_for_selector("#editor-host[data-ready] svg.network-view")


def inside_pane(page, what, margin=8):
    """Every box and every connection line lies wholly within the network pane, the lines
    ``margin`` pixels clear of its edges (a line on the edge reads as running off it)."""
    drawn = page.evaluate(LINES)
    pane = drawn["pane"]
    for b in page.evaluate(BOXES):
        assert (pane["left"] <= b["x"] and b["x"] + b["w"] <= pane["right"] and
                pane["top"] <= b["y"] and b["y"] + b["h"] <= pane["bottom"]), (what, b, pane)
    for line in drawn["lines"]:
        assert (pane["left"] + margin <= line["x0"] and line["x1"] <= pane["right"] - margin and
                pane["top"] + margin <= line["y0"] and line["y1"] <= pane["bottom"] - margin), \
            (what, line, pane)


def no_overlap(rects):
    rects = list(rects)
    for i, a in enumerate(rects):
        for b in rects[i + 1:]:
            apart = (a["x"] + a["w"] <= b["x"] or b["x"] + b["w"] <= a["x"] or
                     a["y"] + a["h"] <= b["y"] or b["y"] + b["h"] <= a["y"])
            assert apart, f"{a['name']} and {b['name']} overlap: {a} {b}"


def far_away_copy(tmp_path):
    """planar_arm_reaching.ikg with every module stored far from the origin."""
    text = open(REACHING, encoding="utf-8").read()
    k = iter(range(100))
    text = re.sub(r"<module ", lambda m: f'<module _x="{4000 + 220 * next(k)}" _y="3000" ', text)
    path = tmp_path / "reaching.ikg"
    path.write_text(text, encoding="utf-8")
    return str(path)


def test_auto_layout_fit_new_modules_and_the_feedback_line(tmp_path):
    """Item 2: Auto layout ends with the graph fitted to the pane (it left a blank canvas);
    new modules go where there is room near the middle of the view, not on one another.
    Item 7: the delay-1 feedback line stays within the pane after Fit. Item 6: the class
    list and the inspector show a description's code as code, not in backticks."""
    def check(server, page):
        page.click("#ed-auto-layout")
        page.wait_for_function("() => document.querySelector('#ed-auto-layout') && "
                               "[...document.querySelectorAll('#editor-host rect.box')].length === 9")
        time.sleep(0.5)
        try:
            inside_pane(page, "after Auto layout")
        finally:
            shot(page, "auto-layout")
        page.click("#ed-fit")
        time.sleep(0.3)
        inside_pane(page, "after Fit")
        feedback = [line for line in page.evaluate(LINES)["lines"]
                    if line["source"] == "Command.OUTPUT"]
        assert len(feedback) == 1

        # new modules: each in a free place, in the view
        for n in range(3):
            page.click("#ed-add-module")
            page.fill(".class-search", "Scale")
            page.click(".class-list li[data-class='Scale']")
            if n == 0:      # item 6: the class list shows code as code
                desc = page.locator(".class-info .class-description")
                assert "`" not in desc.inner_text() and desc.locator("code").count() >= 1
                assert "`" not in page.inner_text(".class-info")
            page.click("#add-module-ok")
            name = "Scale" if n == 0 else f"Scale{n + 1}"
            page.wait_for_function("(n) => document.querySelector(`#editor-host rect.box[data-name='${n}']`)",
                                   arg=name)
        no_overlap(page.evaluate(BOXES))
        pane = page.evaluate(LINES)["pane"]
        for b in page.evaluate(BOXES):
            if b["name"].startswith("Scale"):
                assert pane["left"] <= b["x"] and b["x"] + b["w"] <= pane["right"], (b, pane)
                assert pane["top"] <= b["y"] and b["y"] + b["h"] <= pane["bottom"], (b, pane)
        # item 6: the inspector of the selected new module
        desc = page.locator("#editor-inspector .module-description")
        assert "`" not in desc.inner_text() and desc.locator("code").count() >= 1
        shot(page, "new-modules")

    in_own_browser(far_away_copy(tmp_path), open_editor, check)


PORTS_MODEL = """<?xml version="1.0"?>
<group name="Ports">
    <module class="Constant" name="Source" data="1 2" _x="40" _y="60" />
    <module class="Scale" name="Target" factor="2" _x="420" _y="60" />
    <module class="Constant" name="Other" data="3" _x="40" _y="260" />
    <connection source="Other.OUTPUT" target="Target.INPUT" />
</group>
"""


def drag(page, a, b, steps=10):
    page.mouse.move(*a)
    page.mouse.down()
    for i in range(1, steps + 1):
        page.mouse.move(a[0] + (b[0] - a[0]) * i / steps, a[1] + (b[1] - a[1]) * i / steps)
    page.mouse.up()


def centre(locator):
    r = locator.bounding_box()
    return r["x"] + r["width"] / 2, r["y"] + r["height"] / 2


def test_connecting_from_port_names_with_a_hover_cue_and_moving_by_the_title(tmp_path):
    """Item 3: a port's name starts a connection as its circle does (from an output or from
    an input), the port under the pointer stands out, and the box moves by its title."""
    path = tmp_path / "ports.ikg"
    path.write_text(PORTS_MODEL, encoding="utf-8")

    def port(page, box, side, name, part):
        return page.locator(f"#editor-host g.box-group[data-name='{box}'] .port-{side}"
                            f"[data-port='{name}'] {part}")

    def connected(page, source, target):
        page.wait_for_function(
            "([s, t]) => [...document.querySelectorAll('#editor-host g.edge')].some("
            "(e) => e.dataset.source === s && e.dataset.target === t)", arg=[source, target])

    def check(server, page):
        source_box = page.locator("#editor-host g.box-group[data-name='Source'] rect.box")
        target_box = page.locator("#editor-host g.box-group[data-name='Target'] rect.box")
        before = (source_box.bounding_box(), target_box.bounding_box())

        # the hover cue on a port's name
        label = port(page, "Target", "in", "INPUT", "text.port-name")
        page.mouse.move(*centre(label))
        cue = page.evaluate("""() => {
            const p = document.querySelector("#editor-host g.box-group[data-name='Target'] .port-in[data-port='INPUT']");
            return {hover: p.matches(':hover'), stroke: getComputedStyle(p.querySelector('circle')).strokeWidth,
                    weight: getComputedStyle(p.querySelector('text')).fontWeight}; }""")
        assert cue["hover"] and cue["stroke"] == "3px" and cue["weight"] == "600", cue
        x, y = centre(label)
        under = page.evaluate("([x, y]) => getComputedStyle(document.elementFromPoint(x, y)).cursor", [x, y])
        assert under == "crosshair", under

        # output name -> input name
        drag(page, centre(port(page, "Source", "out", "OUTPUT", "text.port-name")),
             centre(port(page, "Target", "in", "INPUT", "text.port-name")))
        connected(page, "Source.OUTPUT", "Target.INPUT")
        # input name -> output circle: the connection goes from the output
        drag(page, centre(port(page, "Target", "in", "SCALE", "text.port-name")),
             centre(port(page, "Source", "out", "OUTPUT", "circle")))
        connected(page, "Source.OUTPUT", "Target.SCALE")
        assert (source_box.bounding_box(), target_box.bounding_box()) == before   # nothing moved

        # the title moves the box
        title = page.locator("#editor-host g.box-group[data-name='Target'] text.box-name")
        x, y = centre(title)
        drag(page, (x, y), (x + 60, y + 80))
        page.wait_for_function(
            "(x0) => document.querySelector(`#editor-host g.box-group[data-name='Target'] rect.box`)"
            ".getBoundingClientRect().x > x0 + 30", arg=before[1]["x"])
        shot(page, "ports")

    in_own_browser(str(path), open_editor, check)
