"""The view editor in a real headless Chromium against the real server (issue 16): a view
wider than the pane is scaled to fit it, a drag maps screen pixels through the scale, and
the controls of the live widgets act while the view is edited.

Screenshots are kept in test-artifacts/."""
from __future__ import annotations

import math
import os
import time

from browsing import ARTIFACTS, in_own_browser

WIDE = """<?xml version="1.0"?>
<group name="W">
    <module class="Constant" name="A" data="1" />
    <module class="Scale" name="Gain" factor="1" />
    <connection source="A.OUTPUT" target="Gain.INPUT" />
    <view name="Wide">
        <slider-horizontal title="gain" x="20" y="20" width="300" height="80" parameter="Gain.factor"
            min="0" max="2" step="0.5" />
        <plot source="Gain.OUTPUT" title="far" x="2400" y="40" width="400" height="200" />
    </view>
</group>
"""

FRAMES = """() => Object.fromEntries([...document.querySelectorAll('#editor-host .widget-frame')].map((f) => {
    const b = f.getBoundingClientRect(); return [f.dataset.title, [b.x, b.y, b.width, b.height]]; }))"""
HOST = """() => { const h = document.querySelector('#editor-host'); const b = h.getBoundingClientRect();
    return {x: b.x, y: b.y, w: b.width, h: b.height, scrollW: h.scrollWidth, clientW: h.clientWidth,
            scrollH: h.scrollHeight, clientH: h.clientHeight}; }"""
ATTRS = """(title) => window.ikaros.editor.currentView().children.find((w) => w.attrs.title === title).attrs"""


def snapped(v: float, grid: int) -> int:
    return int(math.floor(v / grid + 0.5) * grid)


def drag(page, x, y, dx, dy):
    page.mouse.move(x, y)
    page.mouse.down()
    page.mouse.move(x + dx, y + dy, steps=4)
    page.mouse.up()


def open_view(page):
    page.click("#toggle-editor")
    page.wait_for_selector("#editor-host[data-ready] svg.network-view")
    page.evaluate("() => window.ikaros.editor.openGroup('', 0)")
    page.wait_for_selector("#editor-host .widget-frame[data-title='far'].live")
    page.wait_for_selector("#editor-host .widget-frame[data-title='gain'].live input[type=range]:enabled")


def test_a_wide_view_fits_the_pane_and_drags_map_through_the_scale(tmp_path):
    model = tmp_path / "wide.ikg"
    model.write_text(WIDE)

    def check(server, page):
        open_view(page)
        scale = page.evaluate("() => window.ikaros.editor.viewEditor.scale")
        host = page.evaluate(HOST)
        assert 0.2 < scale < 1, scale
        # the whole view is in the pane: no scroll bar, the far widget's right edge inside
        assert host["scrollW"] <= host["clientW"] and host["scrollH"] <= host["clientH"], host
        frames = page.evaluate(FRAMES)
        x, y, w, h = frames["far"]
        assert x + w <= host["x"] + host["w"] and abs(w - 400 * scale) < 0.01 and abs(h - 200 * scale) < 0.01, (frames, scale)
        os.makedirs(ARTIFACTS, exist_ok=True)
        page.screenshot(path=os.path.join(ARTIFACTS, "view-editor-fit.png"))

        # a drag by (60, 30) screen pixels moves the widget by (60, 30) / scale view units
        grid = page.evaluate("() => window.ikaros.editor.viewEditor.grid")
        drag(page, x + w / 2, y + 6, 60, 30)
        attrs = page.evaluate(ATTRS, "far")
        assert (int(attrs["x"]), int(attrs["y"])) == (snapped(2400 + 60 / scale, grid), snapped(40 + 30 / scale, grid)), (attrs, scale)

        # a corner-handle drag resizes by the same mapping
        frames = page.evaluate(FRAMES)
        scale = page.evaluate("() => window.ikaros.editor.viewEditor.scale")
        x, y, w, h = frames["far"]
        handle = page.locator("#editor-host .widget-frame[data-title='far'] .resize-handle").bounding_box()
        assert abs(handle["width"] - 12) < 0.01, handle       # the same size on screen at any scale
        drag(page, x + w - 6, y + h - 6, -40, 20)
        attrs = page.evaluate(ATTRS, "far")
        assert (int(attrs["width"]), int(attrs["height"])) == (snapped(400 - 40 / scale, grid), snapped(200 + 20 / scale, grid)), (attrs, scale)

        # 100 %: the widgets at their size, the pane scrolls, a drag of N pixels is N units
        page.click("#editor-host button[data-zoom='fit']")
        assert page.get_attribute("#editor-host button[data-zoom='fit']", "aria-pressed") == "false"
        assert page.evaluate("() => window.ikaros.editor.viewEditor.scale") == 1
        host = page.evaluate(HOST)
        assert host["scrollW"] > host["clientW"], host
        x, y, w, h = page.evaluate(FRAMES)["gain"]
        assert (w, h) == (300, 80)
        drag(page, x + 100, y + 6, 30, 20)
        attrs = page.evaluate(ATTRS, "gain")
        assert (int(attrs["x"]), int(attrs["y"])) == (snapped(20 + 30, grid), snapped(20 + 20, grid)), attrs
        page.click("#editor-host button[data-zoom='fit']")
        assert page.evaluate("() => window.ikaros.editor.viewEditor.scale") < 1
        assert not page.errors, page.errors

    in_own_browser(str(model), lambda s, p: None, check)


def test_live_controls_act_while_the_view_is_edited(tmp_path):
    model = tmp_path / "wide.ikg"
    model.write_text(WIDE)

    def check(server, page):
        open_view(page)
        assert server.parameter("Gain.factor") == 1
        slider = page.locator("#editor-host .widget-frame[data-title='gain'] input[type=range]")
        b = slider.bounding_box()
        # the slider's own pointer: its value follows, the parameter changes, the frame
        # neither moves nor becomes selected
        drag(page, b["x"] + b["width"] / 2, b["y"] + b["height"] / 2, b["width"], 0)
        deadline = time.monotonic() + 10
        while server.parameter("Gain.factor") != 2:
            assert time.monotonic() < deadline, server.parameter("Gain.factor")
            time.sleep(0.05)
        assert page.evaluate("() => window.ikaros.editor.selection.size") == 0
        attrs = page.evaluate(ATTRS, "gain")
        assert (attrs["x"], attrs["y"]) == ("20", "20"), attrs
        page.screenshot(path=os.path.join(ARTIFACTS, "view-editor-live-slider.png"))

        # the frame's title selects it for editing (the inspector shows the widget)
        frame = page.locator("#editor-host .widget-frame[data-title='gain']")
        fb = frame.bounding_box()
        page.mouse.click(fb["x"] + fb["width"] / 2, fb["y"] + 5)
        page.wait_for_selector("#editor-host .widget-frame[data-title='gain'].selected")
        assert page.evaluate("() => [...window.ikaros.editor.selection].map((w) => w.attrs.title)") == ["gain"]
        page.wait_for_selector("#editor-inspector input[data-attr='parameter'], #editor-inspector select[data-attr='parameter']")
        # and the slider of the selected frame still acts
        slider = page.locator("#editor-host .widget-frame[data-title='gain'] input[type=range]")
        page.wait_for_selector("#editor-host .widget-frame[data-title='gain'] input[type=range]:enabled")
        b = slider.bounding_box()
        drag(page, b["x"] + b["width"] - 2, b["y"] + b["height"] / 2, -b["width"], 0)
        deadline = time.monotonic() + 10
        while server.parameter("Gain.factor") != 0:
            assert time.monotonic() < deadline, server.parameter("Gain.factor")
            time.sleep(0.05)
        assert not page.errors, page.errors

    in_own_browser(str(model), lambda s, p: None, check)
