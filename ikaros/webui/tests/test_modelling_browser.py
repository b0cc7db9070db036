"""The web UI as a modelling tool (issue 16), in a real headless Chromium against the real
server: each test loads one page and makes several checks on it, each of which failed
before its fix. Screenshots go to a temporary folder (printed with -s)."""
from __future__ import annotations

import os
import tempfile
import time

import numpy as np

from browsing import AXE, ROOT, SERIOUS, in_own_browser

EXAMPLES = os.path.join(ROOT, "examples")
DEMO = os.path.join(EXAMPLES, "demo.ikg")
SHOTS = os.path.join(tempfile.gettempdir(), "ikaros-webui-shots")


def shot(page, name):
    os.makedirs(SHOTS, exist_ok=True)
    page.screenshot(path=os.path.join(SHOTS, f"{name}.png"))


def show_view(page, group: str, index: int):
    page.click(f"#navigator a[data-group='{group}'][data-view='{index}']")
    page.wait_for_function(
        "([g, v]) => { const c = window.ikaros.built; return c && c.group === g && c.view === v; }",
        arg=[group, index])


def wait_for(predicate, timeout=10.0, what="condition"):
    deadline = time.monotonic() + timeout
    while not (value := predicate()):
        if time.monotonic() > deadline:
            raise AssertionError(f"timed out waiting for {what}")
        time.sleep(0.05)
    return value


def measured_rate(server, seconds=1.0):
    t0, n0 = time.monotonic(), server.tick()
    time.sleep(seconds)
    return (server.tick() - n0) / (time.monotonic() - t0)


def test_demo_rates_push_button_and_plots(tmp_path):
    """ticks/s is the rate over the last second after a long pause (defect 1); a push button
    bound to a parameter is released (defect 3)."""
    def check(server, page):
        show_view(page, "", 0)
        page.click("#run-realtime")               # 50 ticks/s (tick_duration 0.02)
        wait_for(lambda: server.tick() > 20, what="ticks")
        page.click("#run-pause")
        time.sleep(2.5)                           # paused time must not count
        page.click("#run-realtime")
        time.sleep(1.5)
        real = measured_rate(server)
        shown = float(page.inner_text("#sys-ticks_per_second"))
        assert abs(shown - real) < 0.15 * real, (shown, real)
        mean = float(page.inner_text("#sys-ticks_per_second_mean"))
        assert abs(mean - 50) < 10, mean         # the run's mean leaves the pause out
        page.click("#run-pause")
        page.wait_for_function(
            "() => document.querySelector('#sys-ticks_per_second').textContent === '-' && "
            "document.querySelector('#sys-actual_tick_duration').textContent === '-'")

        # defect 3: a push button is not left pressed
        button = page.locator("button.button-control:has-text('Boost')")
        box = button.bounding_box()
        page.mouse.move(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
        page.mouse.down()
        wait_for(lambda: server.parameter("Boost.factor") == 3, what="Boost.factor = 3")
        page.mouse.move(box["x"] + box["width"] + 60, box["y"] - 40)  # let go elsewhere
        page.mouse.up()
        wait_for(lambda: server.parameter("Boost.factor") == 1, what="Boost.factor = 1")
        time.sleep(0.3)
        assert button.get_attribute("aria-pressed") != "true"
        assert "on" not in button.get_attribute("class").split()
        assert "pressed" not in button.get_attribute("class").split()
        shot(page, "demo-signals")

        # defect 6: at 1400 px the view fits its pane (no widget cut off on the right)
        right = page.evaluate("""() => Math.max(...[...document.querySelectorAll(
            '#view-host .view > .widget')].map((w) => w.getBoundingClientRect().right))""")
        area = page.locator("#view-area").bounding_box()
        assert right <= area["x"] + area["width"], (right, area)

        # defect 6: the module inspector shows the whole description, code for backticks,
        # and numbers never broken across lines
        page.evaluate("() => window.ikaros.moduleInspector.open('Sine')")
        desc = page.locator("#module-inspector .module-description")
        desc.wait_for()
        assert "`" not in desc.inner_text()
        assert desc.locator("code").count() >= 3
        assert desc.evaluate("(d) => d.scrollHeight <= d.clientHeight + 1")
        page.evaluate("() => window.ikaros.moduleInspector.open('History')")
        page.wait_for_function("""() => [...document.querySelectorAll('#module-inspector .buffer-value')]
            .some((c) => c.textContent.includes(','))""")
        broken = page.evaluate("""() => {
            let n = 0;
            for (const cell of document.querySelectorAll('#module-inspector .buffer-value')) {
                const text = cell.firstChild;
                if (!text) continue;
                const re = /[-0-9.e]+/g;
                let m;
                while ((m = re.exec(text.data))) {
                    const r = document.createRange();
                    r.setStart(text, m.index); r.setEnd(text, m.index + m[0].length);
                    if (r.getClientRects().length > 1) n++;
                }
            }
            return n; }""")
        assert broken == 0

    in_own_browser(DEMO, lambda s, p: None, check)


def test_reaching_view_overlays_and_path_of_rows():
    """Widgets drawn over others are see-through and the path draws an n x 2 chain
    (defect 4)."""
    def check(server, page):
        show_view(page, "", 0)
        server.step(3)
        page.wait_for_function(
            "(t) => window.ikaros.lastFrame && window.ikaros.lastFrame.tick >= t", arg=3)
        time.sleep(0.2)
        backgrounds = page.evaluate("""() => [...document.querySelectorAll('#view-host .widget')]
            .slice(0, 4).map((w) => getComputedStyle(w).backgroundColor)""")
        assert all(b in ("rgba(0, 0, 0, 0)", "transparent") for b in backgrounds[1:]), backgrounds
        # the path (the first widget) draws the arm: dark pixels in its canvas
        dark = page.evaluate("""() => {
            const c = document.querySelector('#view-host .widget[data-widget="path"] canvas');
            const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
            let n = 0;
            for (let i = 0; i < d.length; i += 4) if (d[i + 3] > 200 && d[i] < 60 && d[i + 1] < 60) n++;
            return n; }""")
        assert dark > 200, dark
        shot(page, "reaching")

    in_own_browser(os.path.join(EXAMPLES, "planar_arm_reaching.ikg"), lambda s, p: None,
                   check)


NESTED = """<?xml version="1.0"?>
<group name="T">
    <module class="Constant" name="A" data="1" />
    <group name="G">
        <module class="Constant" name="B" data="2" />
        <group name="H">
            <module class="Constant" name="C" data="3" />
        </group>
        <view name="V">
            <plot source="B.OUTPUT" title="b" x="20" y="20" width="200" height="100" />
            <bar-graph source="B.OUTPUT" title="bars" x="240" y="20" width="200" height="100" />
        </view>
    </group>
</group>
"""


def test_class_picker_and_widget_sources_from_any_group(tmp_path):
    """Scale + Enter adds a Scale; "sine" finds FunctionGenerator (defect 5). A widget's
    source menu offers the outputs of every group, and a search field narrows it
    (defect 6)."""
    model = tmp_path / "nested.ikg"
    model.write_text(NESTED)

    def check(server, page):
        page.click("#toggle-editor")
        page.wait_for_selector("#editor-host[data-ready] svg.network-view")
        page.evaluate("() => window.ikaros.editor.openGroup('G', 0)")
        # the widgets are live while the view is edited: the plot has B's value (2)
        page.wait_for_function("""() => { const v = window.ikaros.editor.viewEditor;
            const p = v && v.live.find((w) => w.attrs.class === 'plot');
            return p && p.hi.length && p.hi[0].at(-1) === 2; }""")
        page.click("#editor-host .widget-frame[data-widget='plot']")
        menu = "#editor-inspector select[data-attr='source']"
        options = page.eval_on_selector_all(menu + " option", "(os) => os.map((o) => o.value)")
        assert {"B.OUTPUT", "H.C.OUTPUT", ".A.OUTPUT"} <= set(options), options
        page.fill("#editor-inspector input[data-search='source']", "c out")
        shown = page.eval_on_selector_all(menu + " option", "(os) => os.filter((o) => !o.hidden && o.value).map((o) => o.value)")
        assert shown == ["H.C.OUTPUT"], shown
        page.select_option(menu, ".A.OUTPUT")
        # every attribute of the class with a control of its type (part 8)
        inspector = "#editor-inspector "
        assert page.get_attribute(inspector + "input[data-attr='buffer_size']", "type") == "number"
        assert page.eval_on_selector_all(inspector + "select[data-attr='auto_range'] option",
                                         "(os) => os.map((o) => o.value)") == ["", "yes", "no"]
        assert page.locator(inspector + "input.color-swatch").count() >= 1
        page.fill(inspector + "input[data-attr='buffer_size']", "300")
        page.press(inspector + "input[data-attr='buffer_size']", "Tab")
        page.select_option(inspector + "select[data-attr='auto_range']", "yes")
        attrs = page.evaluate("() => { const [w] = window.ikaros.editor.selection; return w.attrs; }")
        assert attrs["buffer_size"] == "300" and attrs["auto_range"] == "yes" and \
            attrs["source"] == ".A.OUTPUT", attrs

        # to front, copy the view as XML, and the grid spacing (part 8)
        page.click(inspector + "button[data-action='to-front']")
        titles = page.evaluate("""() => window.ikaros.editor.model.group('G').children
            .filter((c) => c.tag === 'view')[0].children.map((w) => w.attrs.title)""")
        assert titles == ["bars", "b"], titles
        page.context.grant_permissions(["clipboard-read", "clipboard-write"], origin=server.base)
        page.click("#editor-host .widget-frame[data-title='b']")
        page.click(inspector + "button[data-action='copy-xml']")
        page.wait_for_selector(inspector + "button[data-action='copy-xml']:text-is('Copied')")
        xml = page.evaluate("() => navigator.clipboard.readText()")
        assert xml.startswith('<view name="V">') and xml.index('title="bars"') < xml.index('title="b"')
        assert 'buffer_size="300"' in xml and 'source=".A.OUTPUT"' in xml, xml
        page.click("button[data-grid='larger']")
        frame = page.locator("#editor-host .widget-frame[data-title='b']")
        box = frame.bounding_box()
        page.mouse.move(box["x"] + 50, box["y"] + 30)
        page.mouse.down()
        page.mouse.move(box["x"] + 63, box["y"] + 41, steps=3)
        page.mouse.up()
        attrs = page.evaluate("() => { const [w] = window.ikaros.editor.selection; return w.attrs; }")
        assert int(attrs["x"]) % 20 == 0 and int(attrs["y"]) % 20 == 0 and attrs["x"] != "20", attrs
        page.evaluate("() => window.ikaros.editor.openGroup('', -1)")
        page.click("#ed-add-module")
        page.fill(".class-search", "sine")
        page.wait_for_selector(".class-list li[data-class='FunctionGenerator']")
        page.fill(".class-search", "")
        page.type(".class-search", "Scale")
        first = page.locator(".class-list li").first.get_attribute("data-class")
        assert first == "Scale", first
        page.press(".class-search", "Enter")
        page.wait_for_selector("#editor-host rect.box[data-name='Scale']")

        # defect 6: new and pasted modules never land on top of each other
        page.click("#ed-add-module")
        page.fill(".class-search", "Scale")
        page.press(".class-search", "Enter")
        page.click("#editor-host g.box-group[data-name='A'] rect.box")
        page.click("#ed-copy")
        page.click("#ed-paste")
        page.click("#ed-paste")
        page.wait_for_function("() => document.querySelectorAll('#editor-host rect.box').length >= 6")
        rects = page.evaluate("""() => [...document.querySelectorAll('#editor-host rect.box')].map((r) => {
            const b = r.getBoundingClientRect(); return [r.dataset.name, b.x, b.y, b.width, b.height]; })""")
        for i, a in enumerate(rects):
            for b in rects[i + 1:]:
                apart = a[1] + a[3] <= b[1] or b[1] + b[3] <= a[1] or a[2] + a[4] <= b[2] or b[2] + b[4] <= a[2]
                assert apart, (a, b)
        assert not page.errors, page.errors

    in_own_browser(str(model), lambda s, p: None, check)


PLOTS = """<?xml version="1.0"?>
<group name="P">
    <module class="FunctionGenerator" name="Big" type="sin" offset="10" amplitude="5" frequency="0.1" />
    <module class="FunctionGenerator" name="Flip" type="ticksquare" basetime="2" tickduty="1" />
    <view name="Plots">
        <plot source="Big.OUTPUT" title="big" x="20" y="20" width="300" height="200" unit="volt" />
        <plot source="Flip.OUTPUT" title="flip" x="340" y="20" width="300" height="200" buffer_size="2000" />
    </view>
</group>
"""

PLOT_DATA = """(title) => {
    const w = window.ikaros.mainView.widgets.find((w) => w.el.dataset.title === title);
    return {xs: [...w.xs], lo: [...w.lo[0]], hi: [...w.hi[0]]};
}"""

SERIES_PIXELS = """(title) => {
    const c = document.querySelector(`#view-host .widget[data-title='${title}'] canvas`);
    if (!c) return 0;                   // the plot makes its canvas with its first data
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i + 3] > 100 && d[i + 2] > 150 && d[i] < 90) n++;
    return n;
}"""


def test_plots_auto_range_axes_single_sample_and_every_tick(tmp_path):
    """A plot shows its one sample, ranges over the data with labelled axes (defect 6),
    and, played fast, shows every tick of a signal that flips each tick (part 7)."""
    model = tmp_path / "plots.ikg"
    model.write_text(PLOTS)

    def check(server, page):
        page.wait_for_function("() => window.ikaros.built && window.ikaros.mainView.widgets.length === 2")
        page.wait_for_function(f"() => ({SERIES_PIXELS})('big') > 0")       # tick 0 alone
        server.step(5)
        page.wait_for_function(f"() => ({PLOT_DATA})('big').xs.length >= 6")
        axes = page.evaluate("""() => {
            const w = window.ikaros.mainView.widgets.find((w) => w.el.dataset.title === 'big');
            return {labels: w.plot.axes.map((a) => a.label),
                    ticks: w.plot.axes.map((a) => a._values), y: [w.plot.scales.y.min, w.plot.scales.y.max]};
        }""")
        assert axes["labels"] == ["tick", "volt"], axes
        assert len(axes["ticks"][0]) >= 3 and len(axes["ticks"][1]) >= 3, axes   # tick labels
        numbers = [float(v) for v in axes["ticks"][1]]    # 0 (tick 0) to 11.9 (tick 5)
        assert -1 <= min(numbers) <= 0 and 10 <= max(numbers) <= 13, numbers
        assert -1 <= axes["y"][0] <= 0 and 11.9 <= axes["y"][1] <= 13, axes
        assert [float(v) for v in axes["ticks"][0]][0] >= 0, axes     # from the first tick

        server.post("/api/control", {"state": "play"})
        time.sleep(1.0)
        server.post("/api/control", {"state": "pause"})
        time.sleep(0.2)                      # a tick under way when paused ends first
        tick = server.tick()
        assert tick > 300
        page.wait_for_function("(t) => window.ikaros.lastFrame.tick === t", arg=tick)
        time.sleep(0.2)
        d = page.evaluate(PLOT_DATA, "flip")
        xs, lo, hi = d["xs"], d["lo"], d["hi"]
        # the last column begins within its span of the last tick; 2000 ticks are shown
        assert tick - 200 <= xs[-1] <= tick and xs[-1] - xs[0] >= 1900
        for i in range(len(xs) - 1):
            if xs[i + 1] - xs[i] == 1 and lo[i] == hi[i] and lo[i + 1] == hi[i + 1]:
                assert lo[i] != lo[i + 1], (xs[i], lo[i], lo[i + 1])   # flips every tick
            else:                                 # a column of several ticks: both values
                assert (lo[i], hi[i]) == (0, 1), (xs[i], xs[i + 1], lo[i], hi[i])
        shot(page, "plots")
        assert not page.errors, page.errors

    in_own_browser(str(model), lambda s, p: None, check)


WIDGETS = """<?xml version="1.0"?>
<group name="W">
    <module class="FunctionGenerator" name="Spikes" type="ticksquare" basetime="3" tickduty="1" size="4" />
    <module class="Randomizer" name="Noise" outputsize="50" seed="3" />
    <module class="Constant" name="Pts" data="0 1; 1 3; 2 5" />
    <module class="Constant" name="Field" data="[[[1, 0, 1], [0, 1, 0]], [[0, 1, 0], [1, 0, -1]]]" />
    <module class="Constant" name="Box" data="1 2 3 4 5; 2 4 6 8 10" />
    <module class="Constant" name="One" data="1" />
    <module class="Scale" name="SX" factor="0" />
    <module class="Scale" name="SY" factor="0" />
    <connection source="One.OUTPUT" target="SX.INPUT" />
    <connection source="One.OUTPUT" target="SY.INPUT" />
    <module class="Constant" name="Color" data="0.2 0.4 0.6" />
    <module class="Constant" name="Gaze" data="0.5 -0.3" />
    <module class="Constant" name="Pupil" data="0.8 0.2" />
    <module class="Constant" name="Spot" data="0.3 0.7" />
    <module class="Constant" name="Look" data="30 10" />
    <module class="Scale" name="MX" factor="0" />
    <module class="Scale" name="MY" factor="0" />
    <connection source="One.OUTPUT" target="MX.INPUT" />
    <connection source="One.OUTPUT" target="MY.INPUT" />
    <view name="New widgets">
        <event-raster source="Spikes.OUTPUT" title="raster" x="0" y="0" width="300" height="150" history="3000" />
        <scatter-plot source="Pts.OUTPUT" title="scatter" x="300" y="0" width="200" height="150" />
        <histogram source="Noise.OUTPUT" title="histogram" x="500" y="0" width="200" height="150" bins="5" />
        <boxplot source="Box.OUTPUT" title="boxplot" x="700" y="0" width="200" height="150" />
        <polar-plot source="Box.OUTPUT" title="polar" x="0" y="150" width="200" height="150" />
        <vector-field source="Field.OUTPUT" title="vectors" x="200" y="150" width="200" height="150" />
        <joystick x_parameter="SX.factor" y_parameter="SY.factor" title="joystick" x="400" y="150" width="150" height="150" />
        <color-picker parameter="Color.data" title="colour" x="550" y="150" width="150" height="80" />
        <epi-head eye_direction_source="Gaze.OUTPUT" pupil_size_source="Pupil.OUTPUT" title="epi" x="700" y="150" width="150" height="150" />
        <trace source="Spot.OUTPUT" title="trace" x="0" y="300" width="150" height="150" />
        <bar-graph source="Box.OUTPUT" title="bars" x="0" y="450" width="200" height="100" />
        <surface-plot source="Box.OUTPUT" title="surface" x="150" y="300" width="200" height="150" />
        <navigation-hud heading_source="Look.OUTPUT" title="heading" x="350" y="300" width="200" height="80" />
        <pan-tilt-hud source="Look.OUTPUT" title="pantilt" x="550" y="300" width="150" height="100" />
        <button type="radio" parameter="MX.factor" value="0" label="A" x="700" y="300" width="60" height="40" show_title="no" />
        <button type="radio" parameter="MX.factor" value="2" label="B" x="760" y="300" width="60" height="40" show_title="no" />
        <button type="multi" parameter="MY.factor" values="0,1,2" labels="low,mid,high" x="700" y="340" width="120" height="40" show_title="no" />
    </view>
</group>
"""

PAINTED = """(title) => {
    const c = document.querySelector(`#view-host .widget[data-title='${title}'] canvas`);
    if (!c || !c.width) return 0;                // not built yet
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 3; i < d.length; i += 4) if (d[i] > 100) n++;
    return n;
}"""

WIDGET = "(title) => window.ikaros.mainView.widgets.find((w) => w.el.dataset.title === title)"


def test_the_new_widgets(tmp_path):
    """The original's widgets we lacked draw their data (part 8); the event raster gets
    every event of a fast run (part 7); the joystick and the colour picker set parameters."""
    model = tmp_path / "widgets.ikg"
    model.write_text(WIDGETS)

    def check(server, page):
        page.wait_for_function("() => window.ikaros.built && window.ikaros.mainView.widgets.length === 17")
        server.step(1)
        for title in ("scatter", "histogram", "boxplot", "polar", "vectors", "epi", "trace", "raster",
                      "heading", "pantilt"):
            page.wait_for_function(f"() => ({PAINTED})('{title}') > 40", timeout=5000)
        assert page.evaluate(f"() => ({WIDGET})('histogram').counts.reduce((a, b) => a + b)") == 50
        # the surface: a WebGL canvas, read through a 2-D copy; fire colours where the
        # values are high
        page.wait_for_function("""() => {
            const src = document.querySelector("#view-host .widget[data-title='surface'] canvas");
            const c = document.createElement('canvas'); c.width = src.width; c.height = src.height;
            const g = c.getContext('2d'); g.drawImage(src, 0, 0);
            const d = g.getImageData(0, 0, c.width, c.height).data;
            let warm = 0;
            for (let i = 0; i < d.length; i += 4) if (d[i] > 150 && d[i] > d[i + 2] + 60) warm++;
            return warm > 200; }""", timeout=5000)
        # radio buttons of one parameter, and a multi-state button
        page.click("button.button-control:text-is('B')")
        wait_for(lambda: server.parameter("MX.factor") == 2, what="MX.factor = 2")
        page.wait_for_function("""() => {
            const [a, b] = ['A', 'B'].map((t) => [...document.querySelectorAll('button.button-control')].find((x) => x.textContent === t));
            return a.getAttribute('aria-pressed') === 'false' && b.getAttribute('aria-pressed') === 'true'; }""")
        multi = page.locator("button.button-control:text-is('low')")
        multi.click()
        wait_for(lambda: server.parameter("MY.factor") == 1, what="MY.factor = 1")
        page.locator("button.button-control:text-is('mid')").click()
        wait_for(lambda: server.parameter("MY.factor") == 2, what="MY.factor = 2")
        page.wait_for_selector("button.button-control:text-is('high')")
        assert page.evaluate(f"() => ({WIDGET})('boxplot').boxes.map((b) => b.median)") == [3, 6]
        # a bar graph without min and max ranges over its data (0..10 and a margin)
        low, high = page.evaluate(f"() => ({WIDGET})('bars').valueRange")
        assert low <= 0 and 10 < high <= 11, (low, high)

        server.post("/api/control", {"state": "play"})
        time.sleep(1.0)
        server.post("/api/control", {"state": "pause"})
        time.sleep(0.2)                      # a tick under way when paused ends first
        tick = server.tick()
        page.wait_for_function("(t) => window.ikaros.lastFrame.tick === t", arg=tick)
        time.sleep(0.2)
        # ticksquare is 1 on ticks 1, 4, 7, ... (t - 1 divisible by 3), in 4 elements
        count = page.evaluate(f"() => ({WIDGET})('raster').count")
        assert tick > 1000 and count == 4 * ((tick - 1) // 3 + 1), (tick, count)
        assert page.evaluate(f"() => ({WIDGET})('raster').missed") == 0

        pad = page.locator(".widget[data-title='joystick'] .joystick-pad")
        box = pad.bounding_box()
        cx, cy = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
        page.mouse.move(cx, cy)
        page.mouse.down()
        page.mouse.move(cx + box["width"] * 0.3, cy - box["height"] * 0.3, steps=4)
        wait_for(lambda: server.parameter("SX.factor") > 0.5 and server.parameter("SY.factor") > 0.5,
                 what="the joystick's parameters")
        page.mouse.up()
        wait_for(lambda: server.parameter("SX.factor") == 0 and server.parameter("SY.factor") == 0,
                 what="back to the centre")

        page.wait_for_function("() => !document.querySelector('.color-picker').disabled")
        page.evaluate("""() => { const i = document.querySelector('.color-picker');
            i.value = '#ff0080'; i.dispatchEvent(new Event('input')); }""")
        wait_for(lambda: np.allclose(server.parameter("Color.data"), [1.0, 0.0, 128 / 255]),
                 what="the colour")
        shot(page, "new-widgets")
        assert not page.errors, page.errors

    in_own_browser(str(model), lambda s, p: None, check)


VIEW_REPORT = """() => window.ikaros.mainView.widgets.map((w) => {
    const c = w.el.querySelector('canvas');
    let painted = null;
    if (c && c.width && c.height) {
        const copy = document.createElement('canvas'); copy.width = c.width; copy.height = c.height;
        const g = copy.getContext('2d'); g.drawImage(c, 0, 0);
        const d = g.getImageData(0, 0, c.width, c.height).data;
        painted = 0;
        for (let i = 3; i < d.length; i += 4) if (d[i] > 100) painted++;
    }
    return {cls: w.attrs?.class, title: w.el.dataset.title, subs: w.subscriptions().length,
            painted, samples: w.xs ? w.xs.length : null, error: w.el.classList.contains('widget-error')};
})"""

EXAMPLE_MODELS = ["demo.ikg", "hello.ikg", "conditioning.ikg", "planar_arm_reaching.ikg",
                  "qlearning_maze.ikg", "epuck_obstacles.ikg", os.path.join("modules", "World2D_example.ikg"),
                  os.path.join("vision", "depth_objects.ikg")]


def test_every_example_view_draws_its_data():
    """Each view of the examples, after a few ticks: no widget fails to build, every
    widget fed by data draws (a canvas with pixels, a plot with samples), and axe-core finds
    no serious or critical violation on the page. Screenshots of every view are kept."""
    failures = []
    for name in EXAMPLE_MODELS:
        def check(server, page, name=name):
            server.step(3)
            links = page.eval_on_selector_all(
                "#navigator a[data-view]", "(ls) => ls.map((l) => [l.dataset.group, Number(l.dataset.view)])")
            assert links, name
            page.add_script_tag(path=AXE)
            for group, view in links:
                page.evaluate("([g, v]) => window.ikaros.showView(g, v)", [group, view])
                page.wait_for_function(
                    "([g, v]) => { const c = window.ikaros.built; return c && c.group === g && c.view === v; }",
                    arg=[group, view])
                page.wait_for_function(
                    "(t) => window.ikaros.lastFrame && window.ikaros.lastFrame.tick >= t", arg=3)
                time.sleep(0.3)
                shot(page, f"example-{os.path.basename(name)}-{group or 'top'}-{view}")
                for w in page.evaluate(VIEW_REPORT):
                    where = f"{name} {group or 'top'} view {view}: {w['cls']} {w['title']!r}"
                    if w["error"]:
                        failures.append(where + " did not build")
                    elif w["subs"] and w["samples"] is not None and w["samples"] == 0:
                        failures.append(where + " has no samples")
                    elif w["subs"] and w["painted"] is not None and w["painted"] == 0:
                        failures.append(where + " drew nothing")
                failures.extend(f"{name} {group or 'top'} view {view}: {v}" for v in page.evaluate(SERIOUS))
            assert not page.errors, page.errors

        in_own_browser(os.path.join(EXAMPLES, name), lambda s, p: None, check)
    assert not failures, failures
