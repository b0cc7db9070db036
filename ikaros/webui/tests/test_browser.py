"""The browser app in a real headless Chromium, against the real server running
examples/demo.ikg: every widget type shows real data, the run controls, the controls that
change parameters and run commands, the inspectors, the messages and the themes.

Screenshots of the demo views are kept in test-artifacts/."""
from __future__ import annotations

import contextlib
import os
import time

import pytest

from browsing import ARGS, ARTIFACTS, CHROMIUM, ROOT, TIMEOUT, Server, sync_api

DEMO = os.path.join(ROOT, "examples", "demo.ikg")


@pytest.fixture(scope="session")
def server():
    srv = Server(DEMO)
    yield srv
    srv.stop()


@pytest.fixture(scope="session")
def page(server):
    os.makedirs(ARTIFACTS, exist_ok=True)
    with sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
        pg = browser.new_page(viewport={"width": 1600, "height": 1000})
        errors = []
        pg.on("pageerror", lambda e: errors.append(str(e)))
        pg.errors = errors
        pg.set_default_timeout(TIMEOUT)
        pg.goto(server.base + "/")
        pg.wait_for_selector("#navigator .tree-view a")
        pg.wait_for_function("() => window.ikaros && window.ikaros.socket.connected")
        yield pg
        browser.close()


# --- helpers ------------------------------------------------------------------------------

PIXELS = """(el) => {
    const src = el.tagName === 'CANVAS' ? el : el.querySelector('canvas');
    const c = document.createElement('canvas');
    c.width = src.width; c.height = src.height;
    const g = c.getContext('2d');
    g.drawImage(src, 0, 0);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    let painted = 0, red = 0, blue = 0, white = 0, black = 0;
    const colors = new Set();
    for (let i = 0; i < d.length; i += 4) {
        const [r, gg, b, a] = [d[i], d[i+1], d[i+2], d[i+3]];
        if (a < 128) continue;
        painted++;
        colors.add((r >> 4) + ',' + (gg >> 4) + ',' + (b >> 4));
        if (r > 180 && gg < 90 && b < 90) red++;
        if (b > 180 && r < 90 && gg < 90) blue++;
        if (r > 230 && gg > 230 && b > 230) white++;
        if (r < 25 && gg < 25 && b < 25) black++;
    }
    return {painted, red, blue, white, black, colors: colors.size, total: d.length / 4};
}"""


def pixels(page, widget):
    return widget.evaluate(PIXELS)


def widget(page, title=None, cls=None):
    sel = ".view .widget"
    if cls:
        sel += f"[data-widget='{cls}']"
    if title is not None:
        sel += f"[data-title='{title}']"
    loc = page.locator("#view-host " + sel).first
    loc.wait_for()
    return loc


def show_view(page, group: str, index: int):
    page.click(f"#navigator a[data-group='{group}'][data-view='{index}']")
    page.wait_for_function(
        "([g, v]) => { const c = window.ikaros.built; return c && c.group === g && c.view === v; }",
        arg=[group, index])


def control(page, state: str):
    page.click(f"#run-{state}")
    page.wait_for_function("(s) => window.ikaros.status.state === s || s === 'step'", arg=state)


def pause(page, server):
    page.click("#run-pause")
    page.wait_for_function("() => document.querySelector('#run-pause').classList.contains('active')")
    assert server.get("/api/status")["state"] == "pause"


def step(page, server, n: int = 1):
    """Step n ticks and wait until the browser has a data frame of the last one."""
    for _ in range(n):
        before = int(page.inner_text("#tick"))
        page.click("#run-step")
        page.wait_for_function("(t) => Number(document.querySelector('#tick').textContent) > t",
                               arg=before)
    tick = server.get("/api/status")["tick"]
    page.wait_for_function(
        "(t) => window.ikaros.lastFrame && window.ikaros.lastFrame.tick >= t", arg=tick)
    return tick


def wait_for(predicate, timeout=10.0, what="condition"):
    deadline = time.monotonic() + timeout
    while True:
        value = predicate()
        if value:
            return value
        if time.monotonic() > deadline:
            raise AssertionError(f"timed out waiting for {what}")
        time.sleep(0.05)


def screenshot(page, name):
    page.screenshot(path=os.path.join(ARTIFACTS, f"webui-{name}.png"))


def flat(value):
    if isinstance(value, list):
        return [x for v in value for x in flat(v)]
    return [value]


# --- the tests ----------------------------------------------------------------------------

def test_navigator_shows_groups_views_and_modules(page, server):
    net = server.get("/api/network")
    names = page.locator("#navigator .tree-view a").all_text_contents()
    assert "Signals" in names and "Images" in names and "Space" in names
    assert page.locator("#navigator .group-name[data-group='Space']").count() == 1
    modules = page.locator("#navigator .tree-module a").all_text_contents()
    assert {m["name"] for m in net["top"]["modules"]} <= set(modules)
    assert page.inner_text("#file-name") == net["file"]


def test_step_advances_the_tick_by_exactly_one(page, server):
    pause(page, server)
    before = server.get("/api/status")["tick"]
    assert int(page.inner_text("#tick")) == before
    page.click("#run-step")
    page.wait_for_function("(t) => Number(document.querySelector('#tick').textContent) === t + 1",
                           arg=before)
    time.sleep(0.3)
    assert server.get("/api/status")["tick"] == before + 1
    assert int(page.inner_text("#tick")) == before + 1


def test_play_runs_and_the_system_inspector_shows_the_figures(page, server):
    show_view(page, "", 0)
    before = server.get("/api/status")["tick"]
    control(page, "play")
    wait_for(lambda: server.get("/api/status")["tick"] > before + 20, what="ticks")
    page.wait_for_function("() => window.ikaros.uiFigures().updatesPerSecond > 0")
    page.wait_for_function(
        "() => Number(document.querySelector('#sys-tick').textContent) > 0 && "
        "document.querySelector('#sys-ui_rtt').textContent.endsWith('ms')")
    # the rate over the last second is known once the run has run a moment
    page.wait_for_function("() => document.querySelector('#sys-ticks_per_second').textContent !== '-'")
    assert page.inner_text("#sys-state") == "playing"      # the state in words
    assert page.inner_text("#sys-file") == "demo.ikg"
    for key in ["time", "ticks_per_second", "tick_duration", "actual_tick_duration", "lag",
                "cpu_usage", "idle", "ui_updates", "ui_lag"]:
        assert page.inner_text(f"#sys-{key}") not in ("", "-"), key
    assert page.inner_text("#sys-tick_duration") == "20.00 ms"
    control(page, "realtime")
    assert server.get("/api/status")["state"] == "realtime"
    pause(page, server)


def test_signals_view_widgets_show_real_data(page, server):
    show_view(page, "", 0)
    pause(page, server)
    step(page, server, 3)
    # bar graphs: bars drawn
    gate = widget(page, "Gate.OUTPUT", "bar-graph")
    assert pixels(page, gate)["painted"] > 500
    # plot: lines drawn after some ticks
    step(page, server, 5)
    plot = widget(page, "Sine and square", "plot")
    assert pixels(page, plot)["painted"] > 50
    series = page.evaluate("() => window.ikaros.mainView.widgets.find(w => w.attrs.class === 'plot').series")
    mix = flat(server.data("Mix.OUTPUT")["data"]["Mix.OUTPUT"])
    assert len(series) == 2        # select="0,2": two of the three elements
    assert [s[-1] for s in series] == pytest.approx([mix[0], mix[2]], abs=1e-6)
    assert len(series[0]) >= 6
    # table: the values of History.OUTPUT with 2 decimals
    tick = step(page, server)
    data = server.data("History.OUTPUT")
    assert data["tick"] == tick
    cells = widget(page, "History", "table").locator("td").all_inner_texts()
    assert cells == [f"{v:.2f}" for v in flat(data["data"]["History.OUTPUT"])]
    # text from a string parameter, and static text
    page.wait_for_function(
        "() => [...document.querySelectorAll('.widget-text')].some(e => e.textContent.includes('Square is square'))")
    assert "Noise goes through" in page.locator(".widget-text").first.inner_text()
    # rectangle with its label
    assert page.locator(".widget-rectangle .rectangle-label").first.inner_text() == "Controls"
    screenshot(page, "signals")


def test_button_runs_the_modules_command(page, server):
    show_view(page, "", 0)
    pause(page, server)
    step(page, server, 3)
    assert sum(flat(server.data("Histogram.OUTPUT")["data"]["Histogram.OUTPUT"])) > 0
    page.click("button.button-control:has-text('Reset histogram')")
    wait_for(lambda: sum(flat(server.data("Histogram.OUTPUT")["data"]["Histogram.OUTPUT"])) == 0,
             what="the histogram reset")


def test_push_button_sets_a_parameter_while_held(page, server):
    show_view(page, "", 0)
    button = page.locator("button.button-control:has-text('Boost')")
    box = button.bounding_box()
    page.mouse.move(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    page.mouse.down()
    wait_for(lambda: server.parameter("Boost.factor") == 3, what="Boost.factor = 3")
    page.mouse.up()
    wait_for(lambda: server.parameter("Boost.factor") == 1, what="Boost.factor = 1")


@contextlib.contextmanager
def second_page(page):
    """A page of its own (own context, so its own routes), closed afterwards; it is not
    opened yet."""
    context = page.context.browser.new_context(viewport={"width": 1600, "height": 1000})
    fresh = context.new_page()
    fresh.set_default_timeout(TIMEOUT)
    try:
        yield fresh
    finally:
        context.close()


def test_controls_wait_for_their_parameters(page, server):
    """Sliders, switches and menus cannot be used before their parameter's value has
    arrived: used earlier, a slider would step from its minimum and a menu might send the
    wrong kind of value."""
    blocked = "**/api/module?path=*"
    with second_page(page) as fresh:
        fresh.route(blocked, lambda route: route.abort())
        fresh.goto(server.base + "/")
        show_view(fresh, "", 0)
        controls = {"slider-vertical": ".widget-slider-vertical input[type=range]",
                    "slider-horizontal": ".widget-slider-horizontal input[type=range]",
                    "switch": ".widget-switch input[type=checkbox]",
                    "drop-down-menu": ".widget-drop-down-menu select"}
        fresh.wait_for_timeout(1200)                    # two parameter polls, both refused
        for css in controls.values():
            assert fresh.locator(css).first.is_disabled(), css
        fresh.unroute(blocked)
        for css in controls.values():
            sync_api.expect(fresh.locator(css).first).to_be_enabled()
        vertical = fresh.locator(controls["slider-vertical"]).first
        assert float(vertical.input_value()) == pytest.approx(server.parameter("Sine.frequency"))


def test_a_late_first_read_does_not_undo_newer_frames(page, server):
    """The one-off read that fills a new view at once can answer after frames of later
    ticks have come: the frames' values must stay."""
    held = []
    with second_page(page) as fresh:
        fresh.route("**/api/data?*", lambda route: held.append(route))
        fresh.goto(server.base + "/")
        pause(fresh, server)
        show_view(fresh, "", 0)
        wait_for(lambda: held, what="the first read")
        tick = server.step(2)
        fresh.wait_for_function("(t) => window.ikaros.lastFrame && window.ikaros.lastFrame.tick >= t",
                                arg=tick)
        # the read answers now, as if from before the steps
        route = held[0]
        answer = route.fetch().json()
        answer["tick"] = 0
        answer["data"]["Mix.OUTPUT"] = [999.0, 999.0, 999.0]
        route.fulfill(json=answer)
        fresh.unroute("**/api/data?*")
        fresh.wait_for_timeout(300)
        series = fresh.evaluate(
            "() => window.ikaros.mainView.widgets.find(w => w.attrs.class === 'plot').series")
        mix = flat(server.data("Mix.OUTPUT")["data"]["Mix.OUTPUT"])
        assert all(999.0 not in s for s in series)
        assert series[0][-1] == pytest.approx(mix[0], abs=1e-6)


def test_slider_changes_the_output(page, server):
    show_view(page, "", 0)
    pause(page, server)
    slider = page.locator(".widget-slider-horizontal input[type=range]").first
    sync_api.expect(slider).to_be_enabled()     # its parameter's value has arrived
    box = slider.bounding_box()
    page.mouse.click(box["x"] + box["width"] - 1, box["y"] + box["height"] / 2)
    wait_for(lambda: abs(server.parameter("Gain.factor") - 2.0) < 0.02, what="Gain.factor = 2")
    factor = server.parameter("Gain.factor")
    step(page, server)
    d = server.data("Noise.OUTPUT", "Gain.OUTPUT")["data"]
    noise, gain = flat(d["Noise.OUTPUT"]), flat(d["Gain.OUTPUT"])
    assert any(n > 0 for n in noise)
    assert gain == pytest.approx([factor * n for n in noise], rel=1e-5)
    # the value shown beside the slider
    assert page.locator(".widget-slider-horizontal .slider-value").first.inner_text() == f"{factor:.2f}"
    # keyboard on the vertical slider: one step up
    before = server.parameter("Sine.frequency")
    v = page.locator(".widget-slider-vertical input[type=range]").first
    sync_api.expect(v).to_be_enabled()
    assert float(v.input_value()) == pytest.approx(before)
    v.focus()
    page.keyboard.press("ArrowUp")
    wait_for(lambda: server.parameter("Sine.frequency") > before, what="Sine.frequency up")
    # put the gain back
    page.evaluate("() => fetch('/api/parameter', {method: 'POST', headers: {'Content-Type': 'application/json'}, body: JSON.stringify({path: 'Gain.factor', value: 1})})")
    wait_for(lambda: server.parameter("Gain.factor") == 1, what="Gain.factor = 1")


def test_switch_and_drop_down_menu_set_parameters(page, server):
    show_view(page, "", 0)
    pause(page, server)
    box = page.locator(".widget-switch input[type=checkbox]").first
    page.wait_for_function("() => document.querySelector('.widget-switch input').checked === true")
    box.click()
    wait_for(lambda: server.parameter("Gate.open") is False, what="Gate.open = no")
    step(page, server)
    assert all(v == 0 for v in flat(server.data("Gate.OUTPUT")["data"]["Gate.OUTPUT"]))
    box.click()
    wait_for(lambda: server.parameter("Gate.open") is True, what="Gate.open = yes")
    menu = page.locator(".widget-drop-down-menu select").first
    menu.select_option(label="triangle")
    wait_for(lambda: server.parameter("Square.type") == "triangle", what="Square.type")
    page.wait_for_function(
        "() => [...document.querySelectorAll('.widget-text')].some(e => e.textContent.includes('Square is triangle'))")
    menu.select_option(label="square")
    wait_for(lambda: server.parameter("Square.type") == "square", what="Square.type back")


def test_images_view_widgets_show_real_data(page, server):
    show_view(page, "", 1)
    pause(page, server)
    step(page, server, 2)
    for title in ["rgb", "gray", "fire (turning)", "spectrum", "file demo.png"]:
        w = widget(page, title, "image")
        page.wait_for_function("(el) => el.querySelector('canvas').width > 0", arg=w.element_handle())
        wait_for(lambda: pixels(page, w)["painted"] > 1000, what=f"image {title}")
        assert pixels(page, w)["colors"] > 3, title
    # colour maps: the rgb image has colours, the gray one only grays
    gray = widget(page, "gray", "image").evaluate(
        """(el) => { const c = el.querySelector('canvas'); const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
                     let off = 0; for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - d[i+1]) > 8 || Math.abs(d[i+1] - d[i+2]) > 8) off++; return off; }""")
    assert gray == 0
    assert pixels(page, widget(page, "rgb", "image"))["blue"] > 0
    # grid: Pattern cells with the fire map: 1 is white, 0 is black
    grid = widget(page, "Pattern (click a cell)", "grid")
    p = pixels(page, grid)
    assert p["white"] > 100 and p["black"] > 100
    # marker: red points; path: a blue line
    assert pixels(page, widget(page, "Points", "marker"))["red"] > 50
    assert pixels(page, widget(page, "Shape", "path"))["blue"] > 50
    screenshot(page, "images")


def test_grid_click_toggles_a_parameter_cell(page, server):
    show_view(page, "", 1)
    before = server.parameter("Pattern.data")
    grid = widget(page, "Pattern (click a cell)", "grid").locator("canvas")
    box = grid.bounding_box()
    rows, cols = len(before), len(before[0])
    # the cell in row 0, column 1
    grid.click(position={"x": box["width"] / cols * 1.5, "y": box["height"] / rows * 0.5})
    wait_for(lambda: server.parameter("Pattern.data")[0][1] != before[0][1], what="the cell toggled")
    after = server.parameter("Pattern.data")
    assert after[0][1] == (0 if before[0][1] == 1 else 1)
    assert [r for i, r in enumerate(after) if i] == [r for i, r in enumerate(before) if i]
    grid.click(position={"x": box["width"] / cols * 1.5, "y": box["height"] / rows * 0.5})
    wait_for(lambda: server.parameter("Pattern.data") == before, what="the cell back")


def test_space_group_3d_view_and_plot(page, server):
    page.click("#navigator .group-name[data-group='Space']")
    page.wait_for_function("() => window.ikaros.built?.group === 'Space'")
    pause(page, server)
    step(page, server, 3)
    scene = widget(page, "Scene", "canvas3d")
    page.wait_for_function(
        "() => window.ikaros.mainView.widgets.find(w => w.attrs.class === 'canvas3d').transforms.length === 2")
    time.sleep(0.2)
    p = pixels(page, scene)
    assert p["painted"] > 10000          # the scene is drawn
    assert p["red"] > 20                 # the points of the transforms (point_color)
    step(page, server, 5)
    assert pixels(page, widget(page, "Swing", "plot"))["painted"] > 20
    series = page.evaluate("() => window.ikaros.mainView.widgets.find(w => w.attrs.class === 'plot').series")
    swing = flat(server.data("Space.Swing.OUTPUT")["data"]["Space.Swing.OUTPUT"])
    assert series[0][-1] == pytest.approx(swing[0], abs=1e-6)
    screenshot(page, "space")


def test_widgets_are_laid_out_as_the_file_says(page, server):
    net = server.get("/api/network")
    show_view(page, "", 0)
    expected = [(float(w["x"]), float(w["y"]), float(w["width"]), float(w["height"]))
                for w in net["top"]["views"][0]["widgets"]]
    origin = page.locator("#view-host .view").bounding_box()
    boxes = [page.locator("#view-host .view > .widget").nth(i).bounding_box()
             for i in range(len(expected))]
    # a view wider than its pane is scaled to fit it (views.js)
    zoom = page.evaluate("() => Number(document.querySelector('#view-host .view').style.zoom) || 1")
    got = [(round((b["x"] - origin["x"]) / zoom), round((b["y"] - origin["y"]) / zoom),
            round(b["width"] / zoom), round(b["height"] / zoom)) for b in boxes]
    assert got == expected
    # Space (Ikaros 3 <widget> elements, _x and _y) in its own group
    page.click("#navigator .group-name[data-group='Space']")
    page.wait_for_function("() => window.ikaros.built?.group === 'Space'")
    space = net["top"]["groups"][0]["views"][0]["widgets"]
    page.wait_for_function(
        f"() => document.querySelectorAll('#view-host .view > .widget').length === {len(space)}")


def test_module_inspector_shows_and_edits_a_module(page, server):
    show_view(page, "", 0)
    pause(page, server)
    page.click("#navigator .tree-module a[data-module='Sine']")
    page.wait_for_selector("#module-inspector .module-class")
    assert page.inner_text("#module-inspector .module-class") == "FunctionGenerator"
    assert "function of the tick" in page.inner_text("#module-inspector .module-description")
    amp = page.locator("#module-inspector .param-input[data-param='amplitude']")
    assert float(amp.input_value()) == server.parameter("Sine.amplitude")
    page.wait_for_function(
        "() => document.querySelector(\"#module-inspector .buffer-value[data-buffer='Sine.OUTPUT']\").textContent !== ''")
    amp.fill("0.25")
    amp.press("Enter")
    wait_for(lambda: server.parameter("Sine.amplitude") == 0.25, what="amplitude = 0.25")
    step(page, server)
    value = flat(server.data("Sine.OUTPUT")["data"]["Sine.OUTPUT"])[0]
    page.wait_for_function(
        "(v) => Math.abs(Number(document.querySelector(\"#module-inspector .buffer-value[data-buffer='Sine.OUTPUT']\").textContent) - v) < 1e-3",
        arg=value)
    # an option parameter is a menu
    kind = page.locator("#module-inspector select.param-input[data-param='type']")
    assert kind.input_value() == "sin"
    amp.fill("0.5")
    amp.press("Enter")
    wait_for(lambda: server.parameter("Sine.amplitude") == 0.5, what="amplitude back")
    # shapes of the outputs
    assert "[1]" in page.inner_text("#module-inspector")
    page.click("#module-inspector .close")
    assert page.locator("#module-inspector").is_hidden()


def test_messages_show_the_kernels_notifications(page, server):
    pause(page, server)
    page.evaluate("() => fetch('/api/parameter', {method: 'POST', headers: {'Content-Type': 'application/json'}, body: JSON.stringify({path: 'Histogram.max', value: 0})})")
    wait_for(lambda: server.parameter("Histogram.max") == 0, what="Histogram.max = 0")
    step(page, server)
    page.wait_for_function(
        "() => [...document.querySelectorAll('#messages .message')].some(m => m.textContent.includes('max equals min'))")
    row = page.locator("#messages .message", has_text="max equals min").first
    assert "Histogram" in row.inner_text()
    assert "warning" in row.get_attribute("class")
    server.post("/api/parameter", {"path": "Histogram.max", "value": 1})


def test_theme_switch_restyles_the_interface(page, server):
    show_view(page, "", 0)
    style = "() => [getComputedStyle(document.body).backgroundColor, getComputedStyle(document.querySelector('#view-area')).backgroundColor, getComputedStyle(document.querySelector('.widget')).backgroundColor]"
    page.select_option("#theme", "light")
    page.wait_for_function("() => getComputedStyle(document.body).backgroundColor === 'rgb(244, 245, 247)'")
    light = page.evaluate(style)
    page.select_option("#theme", "dark")
    page.wait_for_function("() => getComputedStyle(document.body).backgroundColor === 'rgb(21, 24, 28)'")
    dark = page.evaluate(style)
    assert all(a != b for a, b in zip(light, dark))
    assert page.evaluate("() => document.querySelector('#theme-css').getAttribute('href')").endswith("dark.css")
    screenshot(page, "signals-dark")
    page.select_option("#theme", "light")
    page.wait_for_function("() => getComputedStyle(document.body).backgroundColor === 'rgb(244, 245, 247)'")


def test_no_errors_in_the_page(page):
    assert page.errors == []
