"""Connections stay routed around the boxes when boxes are moved in the network editor
(issue 16, part 10), in a real headless Chromium against the real server: orthogonal
segments only, none through a box, attached to their ports, delay badges on their own
connection and clear of each other and of the boxes, no two connections of different
ports on top of each other; in a flat group of 320 modules too, with its quick layout and
with elkjs's from a Web Worker.

Screenshots are kept in test-artifacts/."""
from __future__ import annotations

import os
import re

import pytest

from browsing import ARTIFACTS, in_own_browser

LOOP = """<?xml version="1.0"?>
<group name="R">
    <module class="Constant" name="A" data="1" />
    <module class="Scale" name="B" />
    <module class="Add" name="C" />
    <module class="Scale" name="D" />
    <module class="Scale" name="E" />
    <module class="Scale" name="F" />
    <connection source="A.OUTPUT" target="B.INPUT" delay="1" />
    <connection source="B.OUTPUT" target="C.INPUT1" delay="2" />
    <connection source="C.OUTPUT" target="D.INPUT" delay="1" />
    <connection source="D.OUTPUT" target="E.INPUT" delay="1" />
    <connection source="E.OUTPUT" target="C.INPUT2" delay="3" />
    <connection source="A.OUTPUT" target="F.INPUT" delay="4" />
    <output name="OUT" source="E.OUTPUT" />
    <view name="V">
        <plot source="E.OUTPUT" title="e" x="20" y="20" width="200" height="100" />
    </view>
</group>
"""

# every box's rectangle, every connection's points and port ends, every badge, in drawing units
DRAWING = """() => {
    const svg = document.querySelector('#editor-host svg');
    const at = (g) => { const m = /translate\\(([-\\d.]+),([-\\d.]+)\\)/.exec(g.getAttribute('transform')); return [+m[1], +m[2]]; };
    const boxes = {};
    for (const g of svg.querySelectorAll('g.box-group')) {
        const [x, y] = at(g), r = g.querySelector('rect.box');
        boxes[g.dataset.key] = [x, y, x + +r.getAttribute('width'), y + +r.getAttribute('height')];
    }
    const port = (key, side, name) => {
        const g = svg.querySelector(`g.box-group[data-key='${key}']`);
        const c = [...g.querySelectorAll(`g.port-${side} circle`)].find((c) => c.parentNode.dataset.port === name);
        const [x, y] = at(g);
        return [x + +c.getAttribute('cx'), y + +c.getAttribute('cy')];
    };
    const editor = window.ikaros.editor;
    const edges = editor.graph.edges.map((e, i) => {
        const g = svg.querySelector(`g.edge[data-edge='${i}']`);
        const d = g.querySelector('path.edge-line').getAttribute('d');
        return {name: (e.node.attrs.source || '') + '>' + (e.node.attrs.target || e.node.attrs.name), d,
            routed: g.classList.contains('routed'), from: e.from.box.key, to: e.to.box.key,
            points: (d.match(/-?[\\d.]+,-?[\\d.]+/g) || []).map((p) => p.split(',').map(Number)),
            start: port(e.from.box.key, 'out', e.from.port), end: port(e.to.box.key, 'in', e.to.port)};
    });
    const labels = [...svg.querySelectorAll('g.edge-label')].map((g) => {
        const r = g.querySelector('rect');
        const box = [+r.getAttribute('x'), +r.getAttribute('y'), +r.getAttribute('x') + +r.getAttribute('width'), +r.getAttribute('y') + +r.getAttribute('height')];
        const path = svg.querySelector(`g.edge[data-edge='${g.dataset.edge}'] path.edge-line`);
        const cx = (box[0] + box[2]) / 2, cy = (box[1] + box[3]) / 2;
        let off = Infinity;
        for (let s = 0, n = path.getTotalLength(); s <= n; s += 0.5) { const p = path.getPointAtLength(s); off = Math.min(off, Math.hypot(p.x - cx, p.y - cy)); }
        return {text: g.querySelector('text').textContent, box, off};
    });
    return {boxes, edges, labels};
}"""


def crosses(p, q, box):
    """Whether segment p-q passes through the interior of the box (1 unit in from its sides)."""
    x0, y0, x1, y1 = box[0] + 1, box[1] + 1, box[2] - 1, box[3] - 1
    return min(p[0], q[0]) < x1 and max(p[0], q[0]) > x0 and min(p[1], q[1]) < y1 and max(p[1], q[1]) > y0


def on_top(p, q, u, v):
    """Whether two segments run along the same line with overlapping spans."""
    for axis in (0, 1):
        other = 1 - axis
        if p[axis] == q[axis] == u[axis] == v[axis]:
            return min(max(p[other], q[other]), max(u[other], v[other])) > max(min(p[other], q[other]), min(u[other], v[other]))
    return False


def overlap(a, b):
    return min(a[2], b[2]) > max(a[0], b[0]) and min(a[3], b[3]) > max(a[1], b[1])


def check_drawing(page, edges=7, badges=("1", "1", "1", "2", "3", "4")):
    """Every connection routed: axis-parallel segments from its output port to its input
    port through no box but its ends'; its badge on it, clear of boxes and badges."""
    r = page.evaluate(DRAWING)
    assert len(r["edges"]) == edges, r["edges"]
    for e in r["edges"]:
        assert e["routed"] and not re.search("[CcQqAa]", e["d"]), e
        pts = e["points"]
        assert max(abs(a - b) for a, b in zip(pts[0], e["start"])) < 0.6, e
        assert max(abs(a - b) for a, b in zip(pts[-1], e["end"])) < 0.6, e
        for p, q in zip(pts, pts[1:]):
            assert p[0] == q[0] or p[1] == q[1], (e["name"], p, q)
            for key, box in r["boxes"].items():
                if key not in (e["from"], e["to"]):
                    assert not crosses(p, q, box), (e["name"], p, q, key, box)
    # connections of different ports never run on top of each other
    for i, e in enumerate(r["edges"]):
        for f in r["edges"][i + 1:]:
            if e["start"] == f["start"] or e["end"] == f["end"]:
                continue                                    # a fan-out or fan-in may share
            for p, q in zip(e["points"], e["points"][1:]):
                for u, v in zip(f["points"], f["points"][1:]):
                    assert not on_top(p, q, u, v), (e["name"], f["name"], p, q, u, v)
    labels = r["labels"]
    assert sorted(x["text"] for x in labels) == list(badges), labels
    for i, x in enumerate(labels):
        assert x["off"] < 1.0, x
        assert not any(overlap(x["box"], b) for b in r["boxes"].values()), (x, r["boxes"])
        assert not any(overlap(x["box"], y["box"]) for y in labels[i + 1:]), labels
    return r


def drag_box(page, name, dx, dy, release=True):
    b = page.locator(f"#editor-host g.box-group[data-name='{name}'] rect.box").bounding_box()
    page.mouse.move(b["x"] + 30, b["y"] + 10)
    page.mouse.down()
    page.mouse.move(b["x"] + 30 + dx, b["y"] + 10 + dy, steps=5)
    if release:
        page.mouse.up()


def test_connections_stay_routed_around_boxes_when_boxes_move(tmp_path):
    model = tmp_path / "loop.ikg"
    model.write_text(LOOP)
    os.makedirs(ARTIFACTS, exist_ok=True)

    def check(server, page):
        page.click("#toggle-editor")
        page.wait_for_selector("#editor-host[data-ready]")
        page.evaluate("() => window.ikaros.editor.openGroup('', -1)")
        page.wait_for_selector("#editor-host[data-ready] svg.network-view")
        page.wait_for_function("() => document.querySelectorAll('#editor-host g.edge.routed').length === 7")
        first = check_drawing(page)
        page.screenshot(path=os.path.join(ARTIFACTS, "routing-0-layout.png"))
        scale = page.evaluate("() => window.ikaros.editor.netView.t.k")

        # D down by 200 drawing units: while dragged and after, every connection routed
        drag_box(page, "D", 0, 200 * scale, release=False)
        check_drawing(page)
        page.mouse.up()
        moved = check_drawing(page)
        assert moved["boxes"]["c:D"][1] - first["boxes"]["c:D"][1] == 200
        # the connections away from D keep elkjs's routes; D's own are new
        before = {e["name"]: e["points"] for e in first["edges"]}
        after = {e["name"]: e["points"] for e in moved["edges"]}
        assert after["A.OUTPUT>B.INPUT"] == before["A.OUTPUT>B.INPUT"]
        assert after["C.OUTPUT>D.INPUT"] != before["C.OUTPUT>D.INPUT"]
        page.screenshot(path=os.path.join(ARTIFACTS, "routing-1-moved.png"))

        # F dropped right onto the middle of the longest run of the route of E -> C: that
        # route now goes around F
        ec = next(e for e in moved["edges"] if e["name"] == "E.OUTPUT>C.INPUT2")
        longest = max(zip(ec["points"], ec["points"][1:]), key=lambda s: abs(s[0][0] - s[1][0]) + abs(s[0][1] - s[1][1]))
        mx, my = (longest[0][0] + longest[1][0]) / 2, (longest[0][1] + longest[1][1]) / 2
        fb = moved["boxes"]["c:F"]
        drag_box(page, "F", (mx - (fb[0] + fb[2]) / 2) * scale, (my - (fb[1] + fb[3]) / 2) * scale)
        dropped = check_drawing(page)
        f = dropped["boxes"]["c:F"]
        assert any(crosses(p, q, f) for p, q in zip(ec["points"], ec["points"][1:])), "F was not dropped on the route"
        page.screenshot(path=os.path.join(ARTIFACTS, "routing-2-dropped-on-a-route.png"))

        # E moved below A, left of its source D: the connection from D turns back around
        # the boxes
        drag_box(page, "E", -1040 * scale, 360 * scale)
        check_drawing(page)
        page.screenshot(path=os.path.join(ARTIFACTS, "routing-3-backwards.png"))

        # the group left and opened again (positions now stored in the file): still routed
        page.evaluate("() => window.ikaros.editor.openGroup('', 0)")
        page.wait_for_selector("#editor-host .view-editor")
        page.evaluate("() => window.ikaros.editor.openGroup('', -1)")
        page.wait_for_function("() => document.querySelectorAll('#editor-host g.edge.routed').length === 7")
        check_drawing(page)
        assert not page.errors, page.errors

    in_own_browser(str(model), lambda s, p: None, check)


CROSSED = """<?xml version="1.0"?>
<group name="X">
    <module class="Constant" name="P" data="1" _x="0" _y="0" />
    <module class="Constant" name="Q" data="2" _x="0" _y="180" />
    <module class="Scale" name="R" _x="400" _y="0" />
    <module class="Scale" name="S" _x="400" _y="150" />
    <connection source="P.OUTPUT" target="S.INPUT" />
    <connection source="Q.OUTPUT" target="R.INPUT" delay="2" />
</group>
"""


def test_stored_positions_are_routed_with_crossing_connections_side_by_side(tmp_path):
    """A file with positions opens routed; two connections that cross in one channel between
    the boxes run side by side there, not on top of each other."""
    model = tmp_path / "crossed.ikg"
    model.write_text(CROSSED)

    def check(server, page):
        page.click("#toggle-editor")
        page.wait_for_selector("#editor-host[data-ready] svg.network-view")
        page.wait_for_function("() => document.querySelectorAll('#editor-host g.edge.routed').length === 2")
        r = check_drawing(page, edges=2, badges=("1", "2"))
        verticals = sorted(p[0] for e in r["edges"] for p, q in zip(e["points"], e["points"][1:]) if p[0] == q[0])
        assert len(verticals) == 2 and verticals[1] - verticals[0] >= 6, r["edges"]
        page.screenshot(path=os.path.join(ARTIFACTS, "routing-crossed.png"))
        assert not page.errors, page.errors

    in_own_browser(str(model), lambda s, p: None, check)


def flat_group(n):
    """A flat group of ``n`` modules: a chain, and from every module a connection that skips
    the next three (over or under them), with delays 1 to 3."""
    lines = ['<?xml version="1.0"?>', '<group name="Big">', '    <module class="Constant" name="M0" data="1" />']
    lines += [f'    <module class="Add" name="M{i}" />' for i in range(1, n)]
    for i in range(1, n):
        lines.append(f'    <connection source="M{i - 1}.OUTPUT" target="M{i}.INPUT1" delay="{1 + i % 3}" />')
        lines.append(f'    <connection source="M{max(0, i - 4)}.OUTPUT" target="M{i}.INPUT2" />')
    return "\n".join(lines + ["</group>", ""])


# boxes, connection points and badges (text, rectangle, connection), read in one go
BIG_DRAWING = """() => {
    const svg = document.querySelector('#editor-host svg');
    const boxes = {};
    for (const g of svg.querySelectorAll('g.box-group')) {
        const m = /translate\\(([-\\d.]+),([-\\d.]+)\\)/.exec(g.getAttribute('transform')), r = g.querySelector('rect.box');
        boxes[g.dataset.key] = [+m[1], +m[2], +m[1] + +r.getAttribute('width'), +m[2] + +r.getAttribute('height')];
    }
    const edges = window.ikaros.editor.graph.edges.map((e, i) => {
        const g = svg.querySelector(`g.edge[data-edge='${i}']`);
        const d = g.querySelector('path.edge-line').getAttribute('d');
        return {i, d, routed: g.classList.contains('routed'), from: e.from.box.key, to: e.to.box.key,
            points: (d.match(/-?[\\d.]+,-?[\\d.]+/g) || []).map((p) => p.split(',').map(Number))};
    });
    const labels = [...svg.querySelectorAll('g.edge-label')].map((g) => {
        const r = g.querySelector('rect');
        return {edge: +g.dataset.edge, text: g.querySelector('text').textContent,
            box: [+r.getAttribute('x'), +r.getAttribute('y'), +r.getAttribute('x') + +r.getAttribute('width'), +r.getAttribute('y') + +r.getAttribute('height')]};
    });
    return {boxes, edges, labels};
}"""


def distance_to_polyline(x, y, pts):
    best = float("inf")
    for p, q in zip(pts, pts[1:]):
        cx, cy = min(max(x, min(p[0], q[0])), max(p[0], q[0])), min(max(y, min(p[1], q[1])), max(p[1], q[1]))
        best = min(best, ((cx - x) ** 2 + (cy - y) ** 2) ** 0.5)
    return best


def check_big_drawing(page, n):
    """Every connection of the flat group routed through no box but its ends'; every badge
    on its own connection, clear of the boxes and of the other badges."""
    page.wait_for_function("() => window.ikaros.editor.routing && !window.ikaros.editor.routing.pending.length", timeout=20_000)
    page.wait_for_function(f"() => document.querySelectorAll('#editor-host g.edge.routed').length === {2 * (n - 1)}", timeout=5_000)
    r = page.evaluate(BIG_DRAWING)
    assert len(r["boxes"]) == n and len(r["edges"]) == 2 * (n - 1)
    # boxes in buckets of 200 units, so that each segment is checked against its neighbours
    buckets = {}
    for key, b in r["boxes"].items():
        for i in range(int(b[0] // 200), int(b[2] // 200) + 1):
            for j in range(int(b[1] // 200), int(b[3] // 200) + 1):
                buckets.setdefault((i, j), []).append((key, b))
    for e in r["edges"]:
        assert e["routed"] and not re.search("[CcQqAa]", e["d"]), e
        for p, q in zip(e["points"], e["points"][1:]):
            assert p[0] == q[0] or p[1] == q[1], (e, p, q)
            near = {key: b for i in range(int(min(p[0], q[0]) // 200), int(max(p[0], q[0]) // 200) + 1)
                    for j in range(int(min(p[1], q[1]) // 200), int(max(p[1], q[1]) // 200) + 1)
                    for key, b in buckets.get((i, j), [])}
            for key, box in near.items():
                if key not in (e["from"], e["to"]):
                    assert not crosses(p, q, box), (e["i"], p, q, key, box)
    labels = r["labels"]
    assert sorted(x["text"] for x in labels) == sorted([str(1 + i % 3) for i in range(1, n)] + ["1"] * (n - 1))
    for i, x in enumerate(labels):
        b = x["box"]
        assert distance_to_polyline((b[0] + b[2]) / 2, (b[1] + b[3]) / 2, r["edges"][x["edge"]]["points"]) < 1.0, x
        assert not any(overlap(b, box) for box in r["boxes"].values()), x
        assert not any(overlap(b, y["box"]) for y in labels[i + 1:]), x
    return r


HOLD_WORKERS = """() => {
    const Real = window.Worker;
    window.heldWorkers = [];
    window.Worker = class extends Real {
        postMessage(m) { window.heldWorkers.push(() => super.postMessage(m)); }
    };
}"""


def test_a_group_of_320_modules_is_routed_around_its_boxes(tmp_path):
    """More than 300 boxes: drawn at once with a quick layout whose connections near the view
    are routed before the first paint, the others while the page idles; then elkjs's layout
    arrives from a Web Worker. Each time all connections run around the boxes, also after a
    box is moved."""
    model = tmp_path / "big.ikg"
    model.write_text(flat_group(320))
    os.makedirs(ARTIFACTS, exist_ok=True)

    def check(server, page):
        # the layout worker's graph is held back until the quick layout is checked
        page.evaluate(HOLD_WORKERS)
        page.click("#toggle-editor")
        page.wait_for_selector("#editor-host[data-ready] svg.network-view")
        # drawn at once with a quick layout, its connections routed by the editor
        assert page.get_attribute("#editor-host", "data-layout") == "quick"
        quick = check_big_drawing(page, 320)
        assert page.get_attribute("#editor-host", "data-layout") == "quick"
        page.evaluate("() => window.heldWorkers.forEach((go) => go())")
        # the quick layout puts the chain in a row: the skips go around the boxes they pass
        skip = next(e for e in quick["edges"] if e["from"] == "c:M10" and e["to"] == "c:M14")
        assert len(skip["points"]) > 2, skip
        # then elkjs's layout from a Web Worker; the chain, far wider than the view, is cut
        # into rows along its columns in both (issue 37, item 4), so the boxes stay where
        # they are and the connections are routed around them again
        page.wait_for_selector("#editor-host[data-layout='automatic']", timeout=20_000)
        first = check_big_drawing(page, 320)
        assert first["boxes"] == quick["boxes"]
        rows = sorted({box[1] for box in first["boxes"].values()})
        assert rows[-1] - rows[0] > 1000, rows
        page.evaluate("() => window.ikaros.editor.netView.setTransform({k: 1, x: 20, y: 150})")
        page.screenshot(path=os.path.join(ARTIFACTS, "routing-big-0.png"))

        # M2 moved down onto the skips' channel: every connection still clear
        drag_box(page, "M2", 0, 150)
        moved = check_big_drawing(page, 320)
        assert abs(moved["boxes"]["c:M2"][1] - first["boxes"]["c:M2"][1] - 150) <= 5   # snapped to 10 units
        page.screenshot(path=os.path.join(ARTIFACTS, "routing-big-1-moved.png"))
        assert not page.errors, page.errors

    in_own_browser(str(model), lambda s, p: None, check)


WIRES = """<?xml version="1.0"?>
<group name="W">
    <module class="FunctionGenerator" name="FG" _x="40" _y="40" />
    <module class="FunctionGenerator" name="FG2" _x="40" _y="300" />
    <module class="Add" name="Add" _x="420" _y="160" />
    <connection source="FG.OUTPUT" target="Add.INPUT1" />
    <connection source="FG2.OUTPUT" target="Add.INPUT2" />
</group>
"""

LANE_GAP = 40


def one_line(p, q, u, v, gap=LANE_GAP):
    """Whether two segments lie on one line with less than ``gap`` between their spans (they
    read as one connection)."""
    for axis in (0, 1):
        other = 1 - axis
        if p[axis] == q[axis] == u[axis] == v[axis]:
            return min(max(p[other], q[other]), max(u[other], v[other])) + gap > \
                max(min(p[other], q[other]), min(u[other], v[other]))
    return False


def test_connections_into_different_inputs_run_in_lanes_of_their_own(tmp_path):
    """Issue 37, item 5: FG into INPUT1 and FG2 into INPUT2 of Add turned up and down on one
    vertical line, 18 units apart: one could not tell which reached which input."""
    model = tmp_path / "wires.ikg"
    model.write_text(WIRES)

    def check(server, page):
        page.click("#toggle-editor")
        page.wait_for_selector("#editor-host[data-ready] svg.network-view")
        r = check_drawing(page, edges=2, badges=("1", "1"))
        (e, f) = r["edges"]
        for p, q in zip(e["points"], e["points"][1:]):
            for u, v in zip(f["points"], f["points"][1:]):
                assert not one_line(p, q, u, v), (p, q, u, v)
        page.screenshot(path=os.path.join(ARTIFACTS, "routing-lanes.png"))
        assert not page.errors, page.errors

    in_own_browser(str(model), lambda s, p: None, check)


def test_new_modules_are_placed_with_room_for_connections(tmp_path):
    """Issue 37, item 5: modules added one after another were placed 20 units apart."""
    model = tmp_path / "empty.ikg"
    model.write_text('<?xml version="1.0"?>\n<group name="E" />\n')

    def check(server, page):
        page.click("#toggle-editor")
        page.wait_for_selector("#editor-host[data-ready] svg.network-view")
        for n, cls in enumerate(("FunctionGenerator", "FunctionGenerator", "Add", "Scale")):
            page.click("#ed-add-module")
            page.fill(".class-search", cls)
            page.click(f".class-list li[data-class='{cls}']")
            page.click("#add-module-ok")
            page.wait_for_function("(n) => document.querySelectorAll('#editor-host g.box-group').length === n",
                                   arg=n + 1)
        boxes = list(page.evaluate(DRAWING)["boxes"].values())
        for i, a in enumerate(boxes):
            for b in boxes[i + 1:]:
                apart_x = max(b[0] - a[2], a[0] - b[2])
                apart_y = max(b[1] - a[3], a[1] - b[3])
                assert apart_x >= 90 or apart_y >= 40, (a, b)
        assert not page.errors, page.errors

    in_own_browser(str(model), lambda s, p: None, check)


@pytest.mark.slow
def test_a_flat_group_of_400_modules_is_laid_out_in_a_grid_that_fit_shows_whole(tmp_path):
    """Issue 37, item 4: Auto layout and Fit on a group of 400 modules left the view at 20 %
    with most modules out of sight. Now the group is a grid of about the view's shape, and
    Fit shows every box."""
    model = tmp_path / "flat.ikg"
    model.write_text('<?xml version="1.0"?>\n<group name="Flat">\n' + "".join(
        f'    <module class="Constant" name="C{i}" data="{i}" />\n' for i in range(400)) + "</group>\n")

    def check(server, page):
        page.click("#toggle-editor")
        page.wait_for_selector("#editor-host[data-ready] svg.network-view")
        page.wait_for_selector("#editor-host[data-layout='automatic']", timeout=30_000)
        page.click("#ed-auto-layout")
        page.wait_for_function("() => !window.ikaros.editor.graph.boxes.some((b) => b.node.attrs._x === undefined)")
        page.click("#ed-fit")
        page.wait_for_timeout(500)
        view = page.locator("#editor-host svg").bounding_box()
        boxes = page.evaluate("""() => [...document.querySelectorAll('#editor-host svg rect.box')].map((r) => {
            const b = r.getBoundingClientRect(); return [b.left, b.top, b.right, b.bottom]; })""")
        assert len(boxes) == 400
        x0, y0 = view["x"], view["y"]
        x1, y1 = x0 + view["width"], y0 + view["height"]
        assert all(x0 <= b[0] and b[2] <= x1 and y0 <= b[1] and b[3] <= y1 for b in boxes), \
            [b for b in boxes if not (x0 <= b[0] and b[2] <= x1 and y0 <= b[1] and b[3] <= y1)][:3]
        # a grid that fills the view's shape: it spans most of the view one way, half the other
        width = max(b[2] for b in boxes) - min(b[0] for b in boxes)
        height = max(b[3] for b in boxes) - min(b[1] for b in boxes)
        assert max(width / view["width"], height / view["height"]) > 0.8, (width, height, view)
        assert min(width / view["width"], height / view["height"]) > 0.5, (width, height, view)
        page.screenshot(path=os.path.join(ARTIFACTS, "layout-400.png"))
        assert not page.errors, page.errors

    in_own_browser(str(model), lambda s, p: None, check)
