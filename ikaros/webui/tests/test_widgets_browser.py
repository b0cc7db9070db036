"""Widgets of issue 16 in a real headless Chromium against the real server: the
target-boxes widget draws its boxes where the rows say, bar graphs have a value axis with
tick labels, and every control of every widget has an accessible name (axe-core finds no
serious violation). Screenshots go to test-artifacts/."""
from __future__ import annotations

import os

from browsing import ARTIFACTS, AXE, SERIOUS, in_own_browser

# Every text a canvas draws, with where it lands on the canvas (in canvas pixels), kept on
# the canvas element: read after clearing the list and redrawing the widget.
RECORD_TEXTS = """() => {
    const fill = CanvasRenderingContext2D.prototype.fillText;
    CanvasRenderingContext2D.prototype.fillText = function (text, x, y, ...rest) {
        const t = this.getTransform();
        (this.canvas.texts ||= []).push({text: String(text), x: t.a * x + t.c * y + t.e,
                                         y: t.b * x + t.d * y + t.f});
        return fill.call(this, text, x, y, ...rest);
    };
}"""

WIDGET = "(title) => window.ikaros.mainView.widgets.find((w) => w.el.dataset.title === title)"

# the texts a widget draws when drawn anew, and its size
DRAWN = f"""(title) => {{
    const w = ({WIDGET})(title);
    w.canvas.texts = [];
    w.draw();
    return {{texts: w.canvas.texts, width: w.width, height: w.height,
             scale: w.canvas.width / w.width, range: w.valueRange}};
}}"""

# the RGBA of canvas pixels [[x, y], ...] of a widget
PIXELS = f"""([title, points]) => {{
    const c = ({WIDGET})(title).canvas;
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    return points.map(([x, y]) => Array.from(d.slice((y * c.width + x) * 4, (y * c.width + x) * 4 + 4)));
}}"""


def serve(tmp_path, text, check):
    model = tmp_path / "widgets.ikg"
    model.write_text(text)

    def open_page(server, page):
        page.add_init_script(script=f"({RECORD_TEXTS})()")
        page.reload()
        page.wait_for_function("() => window.ikaros && window.ikaros.socket.connected")

    def checked(server, page):
        check(server, page)
        assert not page.errors, page.errors

    in_own_browser(str(model), open_page, checked)


def wait_drawn(page, *titles):
    server_tick = "() => window.ikaros.lastFrame && window.ikaros.lastFrame.tick >= 1"
    page.wait_for_function(server_tick)
    for title in titles:
        page.wait_for_function(f"(t) => {{ const w = ({WIDGET})(t); "
                               f"return w && w.width > 0 && (w.boxes || w.rows); }}", arg=title)


# --- target-boxes --------------------------------------------------------------------------

BOXES = """<?xml version="1.0"?>
<group name="T">
    <module class="Constant" name="Targets" data="0.1 0.2 0.4 0.5 0.9; 0 0 0 0 0; 0.6 0.3 0.3 0.6 0.25" />
    <module class="Constant" name="Corners" data="40 20; 119 20; 119 59; 40 59" />
    <view name="Boxes">
        <target-boxes source="Targets.OUTPUT" title="xywh" x="0" y="0" width="300" height="200"
            show_title="no" frame="no" box_color="#ff0000,#00ff00" fill_color="none,#0000ff"
            fill_opacity="0.5" labels="face,,cat" show_score="yes" score_decimals="1" />
        <target-boxes source="Corners.OUTPUT" title="corners" x="300" y="0" width="200" height="100"
            show_title="no" frame="no" box_format="corners" x_max="200" y_max="100" box_color="#ff00ff"
            line_width="4" />
        <target-boxes source="Targets.OUTPUT" title="filtered" x="0" y="200" width="300" height="200"
            show_title="no" frame="no" box_format="center" min_score="0.5" />
    </view>
</group>
"""

RED, GREEN, MAGENTA, CLEAR = [255, 0, 0, 255], [0, 255, 0, 255], [255, 0, 255, 255], [0, 0, 0, 0]


def test_target_boxes_draw_each_row_where_it_says(tmp_path):
    """Rows x, y, w, h (0..1 of the widget) are boxes in their colours; an all-zero row is
    not drawn; a fill with its opacity; labels with scores; corners in pixel coordinates;
    centre boxes and a score threshold."""
    def check(server, page):
        server.step(1)
        wait_drawn(page, "xywh", "corners", "filtered")
        size = page.evaluate(DRAWN, "xywh")
        w, h = size["width"], size["height"]
        assert size["scale"] == 1 and 290 <= w <= 300 and 190 <= h <= 200, size

        def px(fx, fy, dx=0, dy=0, sx=w, sy=h):
            """The canvas pixel at fx, fy (in 0..1, or of sx, sy), moved by dx, dy pixels."""
            return [int(fx * sx) + dx, int(fy * sy) + dy]

        # box 1: x 0.1..0.5, y 0.2..0.7, red, no fill; box 3 (row 3; row 2 is empty):
        # x 0.6..0.9, y 0.3..0.9, green, filled with blue at half opacity; 2 px lines
        points = {"box 1 left": px(0.1, 0.5), "box 1 right": px(0.5, 0.5), "box 1 bottom": px(0.3, 0.7),
                  "box 1 inside": px(0.3, 0.5), "outside": px(0.55, 0.5), "empty row at 0, 0": px(0, 0, 1, 1),
                  "box 1 just outside": px(0.1, 0.5, -3), "box 1 just inside": px(0.1, 0.5, 3),
                  "box 3 left": px(0.6, 0.6), "box 3 right": px(0.9, 0.6), "box 3 bottom": px(0.75, 0.9),
                  "box 3 inside": px(0.75, 0.6)}
        got = dict(zip(points, page.evaluate(PIXELS, ["xywh", list(points.values())])))
        assert got["box 1 left"] == RED and got["box 1 right"] == RED and got["box 1 bottom"] == RED, got
        assert got["box 1 inside"] == CLEAR and got["outside"] == CLEAR, got
        assert got["box 1 just outside"] == CLEAR and got["box 1 just inside"] == CLEAR, got
        assert got["empty row at 0, 0"] == CLEAR, got
        assert got["box 3 left"] == GREEN and got["box 3 right"] == GREEN and got["box 3 bottom"] == GREEN, got
        r, g, b, a = got["box 3 inside"]
        assert (r, g) == (0, 0) and b == 255 and abs(a - 128) <= 1, got
        # the labels, on the boxes' top-left corners (the line's outer edge, 3 px in, 2 px
        # above): "face 0.9" and "cat 0.3"
        texts = [(t["text"], round(t["x"], 2), round(t["y"], 2)) for t in size["texts"]]
        assert texts == [("face 0.9", round(0.1 * w + 2, 2), round(0.2 * h - 2, 2)),
                         ("cat 0.3", round(0.6 * w + 2, 2), round(0.3 * h - 2, 2))], texts
        assert page.evaluate(f"() => ({WIDGET})('xywh').drawn.length") == 2

        # four corners in pixels 0..200 x 0..100: the box 40..119, 20..59, 4 px lines
        size = page.evaluate(DRAWN, "corners")
        assert size["texts"] == []

        def c(x, y, dx=0, dy=0):
            return px(x, y, dx, dy, size["width"] / 200, size["height"] / 100)

        points = [c(40, 40), c(40, 40, -1), c(40, 40, 1), c(119, 40), c(119, 40, 1), c(80, 20), c(80, 59),
                  c(80, 40), c(40, 40, -4), c(119, 40, 4), c(80, 20, 0, -4)]
        got = page.evaluate(PIXELS, ["corners", points])
        assert got == [MAGENTA] * 7 + [CLEAR] * 4, got

        # centre boxes, only the one of score 0.9 (of 0.9, 0 and 0.25): centre (0.1, 0.2),
        # size 0.4 x 0.5 -> x -0.1..0.3, y -0.05..0.45 (cut at the left and the top), in the
        # default colour
        boxes = page.evaluate(f"() => ({WIDGET})('filtered').drawn.map((d) => d.box)")
        assert [[round(v, 3) for v in b] for b in boxes] == [[round(-0.1 * w, 3), round(-0.05 * h, 3),
                                                              round(0.3 * w, 3), round(0.45 * h, 3)]], boxes
        got = page.evaluate(PIXELS, ["filtered", [px(0.3, 0.2), px(0.15, 0.45), px(0.75, 0.6)]])
        assert got[0] == got[1] == [255, 48, 48, 255] and got[2] == CLEAR, got
        page.screenshot(path=os.path.join(ARTIFACTS, "widgets-target-boxes.png"))

        # the view editor edits its attributes with controls of their types
        page.click("#toggle-editor")
        page.wait_for_selector("#editor-host[data-ready] svg.network-view")
        page.evaluate("() => window.ikaros.editor.openGroup('', 0)")
        page.click("#editor-host .widget-frame[data-title='corners']")
        inspector = "#editor-inspector "
        assert page.eval_on_selector_all(inspector + "select[data-attr='box_format'] option",
                                         "(os) => os.map((o) => o.value)") == ["", "xywh", "center", "xyxy", "corners"]
        assert page.input_value(inspector + "select[data-attr='box_format']") == "corners"
        assert page.get_attribute(inspector + "input[data-attr='min_score']", "type") == "number"
        assert page.eval_on_selector_all(inspector + "select[data-attr='show_score'] option",
                                         "(os) => os.map((o) => o.value)") == ["", "yes", "no"]
        page.select_option(inspector + "select[data-attr='box_format']", "xyxy")
        attrs = page.evaluate("() => { const [w] = window.ikaros.editor.selection; return w.attrs; }")
        assert attrs["box_format"] == "xyxy" and attrs["box_color"] == "#ff00ff", attrs

    serve(tmp_path, BOXES, check)


# --- bar graph axes ------------------------------------------------------------------------

BARS = """<?xml version="1.0"?>
<group name="B">
    <module class="Constant" name="Fixed" data="2 8" />
    <module class="Constant" name="Free" data="1 2 3 4 5" />
    <module class="Constant" name="Signed" data="-0.5 0.75" />
    <view name="Bars">
        <bar-graph source="Fixed.OUTPUT" title="fixed" x="0" y="0" width="300" height="200"
            show_title="no" frame="no" min="0" max="10" unit="mV" labels="a,b" fill_color="#0000ff" />
        <bar-graph source="Free.OUTPUT" title="free" x="300" y="0" width="300" height="200"
            show_title="no" frame="no" />
        <bar-graph source="Signed.OUTPUT" title="signed" x="0" y="200" width="320" height="120"
            show_title="no" frame="no" direction="horizontal" min="-1" max="1" labels="left,right" />
        <bar-graph source="Fixed.OUTPUT" title="bare" x="320" y="200" width="200" height="120"
            show_title="no" frame="no" min="0" max="10" show_axis="no" fill_color="#0000ff" />
    </view>
</group>
"""


def test_bar_graphs_have_a_value_axis_with_tick_labels(tmp_path):
    """A given range 0..10 gets the labels 0, 2, ... 10 at their heights and the unit; a
    range that follows the data (1..5 with 0, and a margin) its round values; a horizontal
    graph its value axis at the bottom and its labels on the left; show_axis="no" none."""
    def check(server, page):
        server.step(1)
        wait_drawn(page, "fixed", "free", "signed", "bare")
        fixed = page.evaluate(DRAWN, "fixed")
        w, h = fixed["width"], fixed["height"]
        assert fixed["scale"] == 1 and 290 <= w <= 300 and 190 <= h <= 200, fixed
        # the plotting box of axes.js: left 44, top 6, bottom h - 18, right w - 8
        left, top, bottom, right = 44, 6, h - 18, w - 8
        ticks = [t for t in fixed["texts"] if round(t["x"]) == left - 4]
        assert [t["text"] for t in ticks] == ["0", "2", "4", "6", "8", "10"], fixed["texts"]
        for t in ticks:
            assert abs(t["y"] - (bottom - float(t["text"]) / 10 * (bottom - top))) < 1e-6, t
        # the unit along the value axis, the labels under the bars' centres (slots 0..1, 1..2)
        others = {t["text"]: (round(t["x"], 3), round(t["y"], 3)) for t in fixed["texts"] if t not in ticks}
        slot = (right - left) / 2
        assert others == {"a": (round(left + slot / 2, 3), bottom + 3), "b": (round(left + 1.5 * slot, 3), bottom + 3),
                          "mV": (9, (top + bottom) / 2)}, others
        # the bar of 8: blue from its top (y of 8) down to the axis, nothing above it
        y8 = bottom - 0.8 * (bottom - top)
        x = int(left + 1.5 * slot)
        below, above = page.evaluate(PIXELS, ["fixed", [[x, int(y8) + 2], [x, int(y8) - 3]]])
        assert below == [0, 0, 255, 255] and above[:3] != [0, 0, 255], (below, above)

        free = page.evaluate(DRAWN, "free")
        assert free["range"] == [-0.25, 5.25], free["range"]          # 0..5 and 5 % each side
        assert [t["text"] for t in free["texts"]] == ["0", "2", "4"], free["texts"]

        signed = page.evaluate(DRAWN, "signed")
        w, h = signed["width"], signed["height"]
        bottom = h - 18
        values = [t for t in signed["texts"] if round(t["y"]) == bottom + 3]
        assert [t["text"] for t in values] == ["-1", "-0.5", "0", "0.5", "1"], signed["texts"]
        for t in values:
            assert abs(t["x"] - (44 + (float(t["text"]) + 1) / 2 * (w - 8 - 44))) < 1e-6, t
        labels = [(t["text"], round(t["x"])) for t in signed["texts"] if t not in values]
        assert labels == [("left", 40), ("right", 40)], labels
        left_y, right_y = [t["y"] for t in signed["texts"] if t not in values]
        assert left_y < right_y                                       # the first bar on top

        bare = page.evaluate(DRAWN, "bare")
        assert bare["texts"] == [], bare["texts"]
        # the bar of 8 fills slot 1..2 of 2 (a tenth of a slot each side) up to 0.8 of the
        # height
        w, h = bare["width"], bare["height"]
        inside, over = page.evaluate(PIXELS, ["bare", [[int(0.75 * w), int(0.2 * h) + 2], [int(0.75 * w), int(0.2 * h) - 3]]])
        assert inside == [0, 0, 255, 255] and over[:3] != [0, 0, 255], (inside, over)
        page.screenshot(path=os.path.join(ARTIFACTS, "widgets-bar-graph-axes.png"))

    serve(tmp_path, BARS, check)


# --- accessible controls -------------------------------------------------------------------

CONTROLS = """<?xml version="1.0"?>
<group name="C">
    <module class="Constant" name="Gain" data="0.25" />
    <module class="Constant" name="Levels" data="0.1 0.9" />
    <module class="Constant" name="Mode" data="1" />
    <module class="Constant" name="Color" data="0.2 0.4 0.6" />
    <module class="Constant" name="SX" data="0" />
    <module class="Constant" name="SY" data="0" />
    <view name="Controls">
        <slider-horizontal parameter="Gain.data" labels="gain" x="0" y="0" width="200" height="60" />
        <slider-horizontal parameter="Levels.data" count="2" title="levels" x="200" y="0" width="200" height="90" />
        <slider-vertical parameter="Gain.data" show_title="no" x="400" y="0" width="60" height="160" />
        <drop-down-menu parameter="Mode.data" label="mode" options="off,on,auto" x="0" y="100" width="200" height="60" />
        <drop-down-menu parameter="Mode.data" title="menu" options="off,on,auto" x="200" y="100" width="200" height="60" />
        <switch parameter="Mode.data" show_title="no" x="0" y="170" width="100" height="40" />
        <switch parameter="Levels.data" count="2" title="levels on" x="100" y="170" width="200" height="40" />
        <button command="Gain.reset" show_title="no" x="300" y="170" width="80" height="40" />
        <button type="radio" parameter="Mode.data" value="2" label="auto" show_title="no" x="380" y="170" width="80" height="40" />
        <button type="multi" parameter="Mode.data" values="0,1,2" labels="off,on,auto" show_title="no" x="460" y="170" width="80" height="40" />
        <color-picker parameter="Color.data" title="tint" x="0" y="220" width="150" height="70" />
        <joystick x_parameter="SX.data" y_parameter="SY.data" title="steer" x="150" y="220" width="150" height="150" />
        <text parameter="Gain.data" title="gain value" x="300" y="220" width="150" height="50" />
    </view>
</group>
"""


def test_every_control_has_an_accessible_name(tmp_path):
    """Sliders, menus, check boxes, buttons, the colour picker and the joystick are named by
    their label, else the title, else the parameter (with the element's index when a widget
    has several); sliders carry their value and range, the joystick its x and y; axe-core
    finds no serious or critical violation."""
    def check(server, page):
        page.wait_for_function("() => window.ikaros.built && window.ikaros.mainView.widgets.length === 13")
        page.wait_for_function("() => [...document.querySelectorAll('#view-host input, #view-host select')].every((e) => !e.disabled)")
        role = page.get_by_role
        gain = role("slider", name="gain", exact=True)
        assert gain.input_value() == "0.25"
        assert (gain.get_attribute("min"), gain.get_attribute("max")) == ("0", "1")
        assert [role("slider", name=f"levels {i}", exact=True).input_value() for i in (0, 1)] == ["0.1", "0.9"]
        vertical = role("slider", name="Gain.data", exact=True)
        assert vertical.get_attribute("aria-orientation") == "vertical"
        assert role("combobox", name="mode", exact=True).input_value() == "1"
        assert role("combobox", name="menu", exact=True).count() == 1
        assert role("checkbox", name="Mode.data", exact=True).is_checked()
        assert [role("checkbox", name=f"levels on {i}", exact=True).count() for i in (0, 1)] == [1, 1]
        assert role("button", name="auto", exact=True).get_attribute("aria-pressed") == "false"
        assert role("button", name="on", exact=True).count() == 1            # multi-state at 1
        assert role("button", name="Button", exact=True).count() == 1
        assert page.get_by_label("tint", exact=True).get_attribute("type") == "color"

        stick = role("slider", name="steer", exact=True)
        assert stick.get_attribute("aria-roledescription") == "joystick"
        assert [stick.get_attribute(a) for a in ("aria-valuemin", "aria-valuemax", "aria-valuenow")] == ["-1", "1", "0"]
        stick.focus()
        page.keyboard.press("ArrowRight")
        page.keyboard.press("ArrowDown")
        page.keyboard.press("ArrowDown")
        assert stick.get_attribute("aria-valuenow") == "0.1"
        assert stick.get_attribute("aria-valuetext") == "x 0.10, y -0.20"

        page.add_script_tag(path=AXE)
        assert page.evaluate(SERIOUS) == []
        page.screenshot(path=os.path.join(ARTIFACTS, "widgets-controls.png"))

    serve(tmp_path, CONTROLS, check)
