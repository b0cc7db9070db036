"""The network editor in a real headless Chromium, against the real server running a copy of
a model in tmp_path: building a model from nothing and saving it, the automatic layout of a
file without positions, delete and undo, rename and delete across groups, and an invalid edit
that leaves the previous network running.

Screenshots are kept in test-artifacts/."""
from __future__ import annotations

import os
import shutil
import time

import numpy as np

from browsing import ARTIFACTS, ROOT, in_own_browser

ADD_EXAMPLE = os.path.join(ROOT, "examples", "modules", "Add_example.ikg")
ADDRESSING = os.path.join(ROOT, "tests", "conformance", "models", "addressing.ikg")



def in_browser(model: str, check):
    """Serve a model, open the app in Chromium, switch the editor on and run
    check(server, page); the page must raise no JavaScript error."""
    def open_editor(server, page):
        page.click("#toggle-editor")
        page.wait_for_selector("#editor-host[data-ready] svg.network-view")

    def checked(server, page):
        check(server, page)
        assert not page.errors, page.errors

    in_own_browser(model, open_editor, checked)


# --- helpers ------------------------------------------------------------------------------

BOXES = """() => [...document.querySelectorAll('#editor-host svg rect.box')].map((r) => {
    const b = r.getBoundingClientRect();
    return {name: r.dataset.name, kind: r.dataset.kind, x: b.x, y: b.y, w: b.width, h: b.height};
})"""

EDGES = """() => [...document.querySelectorAll('#editor-host svg g.edge:not(.output-source)')].map(
    (e) => [e.dataset.source, e.dataset.target])"""


def boxes(page):
    return {b["name"]: b for b in page.evaluate(BOXES)}


def edges(page):
    return sorted(tuple(e) for e in page.evaluate(EDGES))


def wait_edges(page, expected):
    """Wait until the drawn connections are the expected (source, target) pairs."""
    expected = sorted(list(e) for e in expected)
    page.wait_for_function(
        "([q, want]) => JSON.stringify(eval(q)().sort()) === JSON.stringify(want)", arg=[EDGES, expected])


def box(page, name):
    return page.locator(f"#editor-host g.box-group[data-name='{name}'] rect.box")


def wait_boxes(page, names):
    page.wait_for_function(
        "(names) => names.every((n) => document.querySelector(`#editor-host rect.box[data-name='${n}']`))",
        arg=list(names))


def add_module(page, cls):
    page.click("#ed-add-module")
    page.fill(".class-search", cls)
    page.click(f".class-list li[data-class='{cls}']")
    info = page.inner_text(".class-info")
    assert cls in info and "Outputs" in info      # the class's description is shown
    page.click("#add-module-ok")
    wait_boxes(page, [cls])


def connect(page, source, output, target, input_):
    """Drag from an output port to an input port."""
    a = page.locator(f"#editor-host g.box-group[data-name='{source}'] .port-out[data-port='{output}'] circle")
    b = page.locator(f"#editor-host g.box-group[data-name='{target}'] .port-in[data-port='{input_}'] circle")
    pa, pb = a.bounding_box(), b.bounding_box()
    page.mouse.move(pa["x"] + pa["width"] / 2, pa["y"] + pa["height"] / 2)
    page.mouse.down()
    for i in range(1, 11):
        page.mouse.move(pa["x"] + (pb["x"] - pa["x"]) * i / 10 + pb["width"] / 2,
                        pa["y"] + (pb["y"] - pa["y"]) * i / 10 + pb["height"] / 2)
    page.mouse.up()
    page.wait_for_function(
        "([s, t]) => [...document.querySelectorAll('#editor-host g.edge')].some((e) => e.dataset.source === s && e.dataset.target === t)",
        arg=[f"{source}.{output}", f"{target}.{input_}"])


def set_param(page, name, value):
    field = page.locator(f"#editor-inspector [data-param='{name}']")
    field.fill(value)
    field.press("Tab")


def answer(page, selector, text):
    page.fill(selector, text)
    page.click("#dialog-ok")


def no_overlap(rects):
    rects = list(rects)
    for i, a in enumerate(rects):
        for b in rects[i + 1:]:
            apart = (a["x"] + a["w"] <= b["x"] or b["x"] + b["w"] <= a["x"] or
                     a["y"] + a["h"] <= b["y"] or b["y"] + b["h"] <= a["y"])
            assert apart, f"{a['name']} and {b['name']} overlap: {a} {b}"


def wait_ticks(server, more=3, timeout=20):
    start = server.tick()
    deadline = time.monotonic() + timeout
    while server.tick() < start + more:
        assert time.monotonic() < deadline, "the network does not run"
        time.sleep(0.05)


# --- the tests ----------------------------------------------------------------------------

def test_build_a_model_from_nothing_and_save_it(tmp_path):
    shutil.copy(ADD_EXAMPLE, tmp_path / "start.ikg")

    def check(server, page):
        page.click("#ed-new")
        answer(page, "#new-name", "Built")
        page.wait_for_function("() => document.querySelector('#editor-crumbs').textContent.includes('Built')")
        page.wait_for_function("() => document.querySelectorAll('#editor-host rect.box').length === 0")

        add_module(page, "Constant")
        set_param(page, "data", "1 2")
        add_module(page, "Scale")
        set_param(page, "factor", "3")
        add_module(page, "Abs")
        no_overlap(boxes(page).values())
        connect(page, "Constant", "OUTPUT", "Scale", "INPUT")
        connect(page, "Scale", "OUTPUT", "Abs", "INPUT")
        assert edges(page) == [("Constant.OUTPUT", "Scale.INPUT"), ("Scale.OUTPUT", "Abs.INPUT")]
        # every connection is labelled with its delay
        labels = page.eval_on_selector_all("#editor-host .edge-label text", "(ts) => ts.map((t) => t.textContent)")
        assert labels == ["1", "1"]

        # a view with a plot of Abs.OUTPUT, its source picked from what the group has
        page.click("#ed-add-view")
        answer(page, "#dialog-input", "Main")
        page.wait_for_selector(".editor-tab.view-tab.current")
        page.select_option("#ed-add-widget", "plot")
        page.wait_for_selector("#editor-host .widget-frame[data-widget='plot']")
        options = page.eval_on_selector_all("#editor-inspector select[data-attr='source'] option", "(os) => os.map((o) => o.value)")
        assert {"Constant.OUTPUT", "Scale.OUTPUT", "Abs.OUTPUT"} <= set(options)
        page.select_option("#editor-inspector select[data-attr='source']", "Abs.OUTPUT")
        page.screenshot(path=os.path.join(ARTIFACTS, "editor-built-view.png"))
        page.click(".editor-tab[data-mode='network']")
        page.wait_for_selector("#editor-host svg rect.box[data-name='Abs']")
        page.screenshot(path=os.path.join(ARTIFACTS, "editor-built-network.png"))

        # apply: the edited network runs
        page.click("#ed-apply")
        page.wait_for_function("() => document.querySelector('#editor-status').dataset.level === 'ok'")
        assert "kept their state" in page.inner_text("#editor-status")
        deadline = time.monotonic() + 20
        for n in (1, 2, 3):     # two connections of delay 1: the data is through at tick 3
            server.post("/api/control", {"state": "step"})
            while server.tick() < n:
                assert time.monotonic() < deadline
                time.sleep(0.05)
        assert server.get("/api/data?paths=Abs.OUTPUT")["data"]["Abs.OUTPUT"] == [3, 6]

        page.click("#ed-save-as")
        answer(page, "#save-as-name", "built.ikg")
        page.wait_for_function("() => document.querySelector('#editor-status').textContent.includes('Saved built.ikg')")

    in_browser(str(tmp_path / "start.ikg"), check)

    import ikaros
    saved = tmp_path / "built.ikg"
    text = saved.read_text()
    assert "<plot" in text and 'source="Abs.OUTPUT"' in text
    net = ikaros.load(str(saved))
    try:
        net.run(3)
        assert np.allclose(net.output("Abs.OUTPUT"), [3, 6])
        assert np.allclose(net.output("Scale.OUTPUT"), [3, 6])
    finally:
        net.close()


def test_a_file_without_positions_is_laid_out_without_overlap(tmp_path):
    shutil.copy(ADDRESSING, tmp_path / "addressing.ikg")

    def check(server, page):
        wait_boxes(page, ["TopC", "Down", "G1", "Abs"])
        assert page.get_attribute("#editor-host", "data-layout") == "automatic"
        placed = boxes(page)
        assert {"TopC", "Down", "G1", "Abs"} <= set(placed)
        no_overlap(placed.values())
        # left to right along the data flow
        assert placed["TopC"]["x"] < placed["Down"]["x"] or placed["G1"]["x"] < placed["Down"]["x"]
        page.screenshot(path=os.path.join(ARTIFACTS, "editor-layout-top.png"))
        # double-click a group to enter it; the navigator follows
        box(page, "G1").dblclick()
        wait_boxes(page, ["G2", "Other"])
        assert "G1" in page.inner_text("#editor-crumbs")
        assert page.locator("#navigator a.group-name[data-group='G1']").count() == 1
        no_overlap(boxes(page).values())
        box(page, "G2").dblclick()
        wait_boxes(page, ["G", "G3"])
        no_overlap(boxes(page).values())
        page.screenshot(path=os.path.join(ARTIFACTS, "editor-layout-g2.png"))

    in_browser(str(tmp_path / "addressing.ikg"), check)


def test_delete_a_module_and_undo(tmp_path):
    shutil.copy(ADD_EXAMPLE, tmp_path / "add.ikg")

    def check(server, page):
        wait_boxes(page, ["Ramp", "Offset", "Add"])
        before = edges(page)
        assert before == [("Offset.OUTPUT", "Add.INPUT2"), ("Ramp.OUTPUT", "Add.INPUT1")]
        box(page, "Ramp").click()
        page.keyboard.press("Delete")
        page.wait_for_function("() => !document.querySelector(\"#editor-host rect.box[data-name='Ramp']\")")
        assert edges(page) == [("Offset.OUTPUT", "Add.INPUT2")]
        page.click("#ed-undo")
        wait_boxes(page, ["Ramp"])
        assert edges(page) == before
        page.click("#ed-redo")
        page.wait_for_function("() => !document.querySelector(\"#editor-host rect.box[data-name='Ramp']\")")
        page.keyboard.press("Control+z")
        wait_boxes(page, ["Ramp"])
        assert edges(page) == before

    in_browser(str(tmp_path / "add.ikg"), check)


def rename(page, name, new_name):
    box(page, name).click()
    field = page.locator("#editor-inspector input[data-attr='name']")
    field.fill(new_name)
    field.press("Tab")
    wait_boxes(page, [new_name])


def test_rename_and_delete_reach_addresses_in_every_group(tmp_path):
    # the addressing model with a view whose widgets name TopC and C
    head, _, _ = open(ADDRESSING).read().rpartition("</group>")
    text = head + """
    <view name="V">
        <plot source="G1.G2.G3.C.OUTPUT" x="0" y="0" width="200" height="100"/>
        <grid-world module="TopC" x="0" y="100" width="200" height="200"/>
    </view>
</group>"""
    (tmp_path / "addressing.ikg").write_text(text)

    def check(server, page):
        wait_boxes(page, ["TopC", "Down", "G1", "Abs"])
        # Abs is reached from G3 only (G1.Other.D.OUTPUT -> .Abs.INPUT): that goes with it
        box(page, "Abs").click()
        page.keyboard.press("Delete")
        page.wait_for_function("() => !document.querySelector(\"#editor-host rect.box[data-name='Abs']\")")
        # TopC is reached from G3 by climbing: G2.G1.Main.TopC.OUTPUT
        rename(page, "TopC", "Top")
        box(page, "G1").dblclick()
        wait_boxes(page, ["G2", "Other"])
        box(page, "G2").dblclick()
        wait_boxes(page, ["G", "G3"])
        box(page, "G3").dblclick()
        wait_boxes(page, ["C"])
        # C is reached from the top (relative), from G3 (by name) and absolutely (.G1...)
        rename(page, "C", "K")
        page.click("#ed-save")
        page.wait_for_function("() => document.querySelector('#editor-status').textContent.includes('Saved')")

    in_browser(str(tmp_path / "addressing.ikg"), check)

    import ikaros
    text = (tmp_path / "addressing.ikg").read_text()
    for address in ('source="G1.G2.G3.K.OUTPUT"', 'source="G2.G1.Main.Top.OUTPUT"',
                    'source="K.OUTPUT"', 'source=".G1.G2.G3.K.OUTPUT"', 'module="Top"'):
        assert address in text
    assert text.count('source="G1.G2.G3.K.OUTPUT"') == 2     # the connection and the plot
    assert "TopC" not in text and '"C.OUTPUT"' not in text and "Abs" not in text
    net = ikaros.load(str(tmp_path / "addressing.ikg"))
    try:
        net.run(3)
        assert net.output("Down.INPUT").tolist() == [3.0]      # from K, at the top
        # an Ikaros 2 file: the connection declared last first (absolute, relative, climbing)
        assert net.output("G1.G2.G.INPUT").tolist() == [3.0, 3.0, 7.0]
    finally:
        net.close()


PORTS = """<?xml version="1.0"?>
<group name="Top">
    <module class="Constant" name="C" data="1 2 3"/>
    <group name="H">
        <input name="IN"/>
        <output name="OUT"/>
        <output name="IN"/>
        <module class="Scale" name="A" factor="2"/>
        <connection source="IN" target="A.INPUT" delay="0"/>
        <connection source="A.OUTPUT" target="OUT" delay="0"/>
        <connection source="A.OUTPUT" target="IN" delay="0"/>
        <group name="Deep">
            <module class="Scale" name="D" factor="10"/>
            <connection source="H.IN" target="D.INPUT" delay="0"/>
        </group>
    </group>
    <module class="Scale" name="Y"/>
    <module class="Scale" name="Z"/>
    <connection source="C.OUTPUT" target="H.IN" delay="0"/>
    <connection source="H.OUT" target="Y.INPUT" delay="0"/>
    <connection source="H.IN" target="Z.INPUT" delay="0"/>
</group>
"""


def test_renaming_group_ports_and_the_open_group_updates_addresses(tmp_path):
    # H has an input and an output both named IN: renaming the input must leave the
    # addresses of the output alone (a source outside H or a target inside H)
    (tmp_path / "ports.ikg").write_text(PORTS)

    def rename_selected(page, new_name):
        field = page.locator("#editor-inspector input[data-attr='name']")
        field.fill(new_name)
        field.press("Tab")

    def check(server, page):
        wait_boxes(page, ["C", "H", "Y", "Z"])
        box(page, "H").dblclick()
        wait_boxes(page, ["A", "Deep", "OUT"])
        page.locator("#editor-host g.box-group[data-name='IN'][data-kind='input'] rect.box").click()
        rename_selected(page, "SENSE")
        wait_boxes(page, ["SENSE"])
        box(page, "OUT").click()
        rename_selected(page, "MOTOR")
        wait_boxes(page, ["MOTOR"])
        page.locator("#editor-host svg.network-view").click(position={"x": 3, "y": 3})
        page.wait_for_function(
            "() => document.querySelector('#editor-inspector .module-class').textContent.includes('(open)')")
        rename_selected(page, "Arm")
        page.wait_for_function(
            "() => document.querySelector('#editor-inspector .module-class').textContent === 'group Arm (open)'")
        wait_boxes(page, ["A", "Deep", "SENSE", "MOTOR"])        # still inside the group
        page.click("#ed-save")
        page.wait_for_function("() => document.querySelector('#editor-status').textContent.includes('Saved')")

    in_browser(str(tmp_path / "ports.ikg"), check)

    import ikaros
    text = (tmp_path / "ports.ikg").read_text()
    for element in ('<group name="Arm">', '<input name="SENSE"/>', '<output name="MOTOR"/>',
                    '<output name="IN"/>',
                    '<connection source="SENSE" target="A.INPUT" delay="0"/>',
                    '<connection source="A.OUTPUT" target="MOTOR" delay="0"/>',
                    '<connection source="A.OUTPUT" target="IN" delay="0"/>',
                    '<connection source="Arm.SENSE" target="D.INPUT" delay="0"/>',
                    '<connection source="C.OUTPUT" target="Arm.SENSE" delay="0"/>',
                    '<connection source="Arm.MOTOR" target="Y.INPUT" delay="0"/>',
                    '<connection source="Arm.IN" target="Z.INPUT" delay="0"/>'):
        assert element in text, element
    net = ikaros.load(str(tmp_path / "ports.ikg"))
    try:
        net.step()
        assert net.output("Y.OUTPUT").tolist() == [2.0, 4.0, 6.0]
        assert net.output("Z.OUTPUT").tolist() == [2.0, 4.0, 6.0]
        assert net.output("Arm.Deep.D.OUTPUT").tolist() == [10.0, 20.0, 30.0]
    finally:
        net.close()


IKAROS3_WIDGETS = """<?xml version="1.0"?>
<group name="W">
    <module class="Constant" name="C" data="1 2 3"/>
    <widget class="plot" name="P" source="C.OUTPUT" _x="10" _y="10" width="200" height="100"/>
</group>
"""


def test_widgets_placed_in_a_group_are_edited_as_a_view(tmp_path):
    (tmp_path / "w.ikg").write_text(IKAROS3_WIDGETS)

    def check(server, page):
        wait_boxes(page, ["C"])
        page.click(".editor-tab.view-tab:has-text('Widgets')")
        page.wait_for_selector("#editor-host .widget-frame[data-widget='plot']")
        page.select_option("#ed-add-widget", "bar-graph")
        page.wait_for_selector("#editor-host .widget-frame[data-widget='bar-graph']")
        page.click("#ed-save")
        page.wait_for_function("() => document.querySelector('#editor-status').textContent.includes('Saved')")

    in_browser(str(tmp_path / "w.ikg"), check)
    text = (tmp_path / "w.ikg").read_text()
    assert '<widget class="plot" name="P" source="C.OUTPUT"' in text
    assert '<widget class="bar-graph" title="bar-graph"' in text and "<view" not in text


def test_an_invalid_edit_shows_the_error_and_the_network_keeps_running(tmp_path):
    shutil.copy(ADD_EXAMPLE, tmp_path / "add.ikg")

    def check(server, page):
        wait_boxes(page, ["Ramp", "Offset", "Add"])
        server.post("/api/control", {"state": "play"})
        wait_ticks(server)
        # a zero-delay cycle: Add.OUTPUT back into Add.INPUT2 with delay 0
        connect(page, "Add", "OUTPUT", "Add", "INPUT2")
        page.fill("#editor-inspector [data-attr='delay']", "0")
        page.press("#editor-inspector [data-attr='delay']", "Tab")
        page.wait_for_function("() => [...document.querySelectorAll('#editor-host .edge-label text')].filter((t) => t.textContent === '0').length === 3")
        page.click("#ed-apply")
        note = page.locator("#editor-host .error-note .editor-error")
        note.wait_for()
        assert "zero-delay cycle" in note.inner_text()
        assert page.locator("#editor-host g.edge.has-error").count() == 1
        bad = page.locator("#editor-host g.edge.has-error")
        assert bad.get_attribute("data-source") == "Add.OUTPUT"
        assert bad.get_attribute("data-target") == "Add.INPUT2"
        # the note is next to the connection's label
        label = page.locator("#editor-host g.edge-label").nth(2).bounding_box()
        nb = note.bounding_box()
        assert abs(nb["y"] - label["y"]) < 80
        assert "previous network keeps running" in page.inner_text("#editor-status")
        page.screenshot(path=os.path.join(ARTIFACTS, "editor-invalid-edit.png"))
        # the previous network still runs
        wait_ticks(server)
        assert server.get("/api/status")["state"] == "play"
        assert len(server.get("/api/network")["top"]["modules"]) == 3
        # undo the bad edit and apply: accepted
        page.click("#ed-undo")
        page.click("#ed-undo")
        wait_edges(page, [("Offset.OUTPUT", "Add.INPUT2"), ("Ramp.OUTPUT", "Add.INPUT1")])
        page.click("#ed-apply")
        page.wait_for_function("() => document.querySelector('#editor-status').dataset.level === 'ok'")
        wait_ticks(server)

    in_browser(str(tmp_path / "add.ikg"), check)
