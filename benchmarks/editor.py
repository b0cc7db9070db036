"""Web UI editor benchmark: first paint, zoom and pan of big groups in headless Chromium.

    python benchmarks/editor.py     # robot_320 (its top group), chains of 320 and 2000 modules,
                                    # a chain of 2000 with connections that skip 3 modules

For each model (benchmarks/models.py and skip_chain below, written to a temporary folder)
it serves the model with ``ikaros -w PORT`` on 127.0.0.1, opens the page in
/usr/bin/chromium, lets the page idle (the class list arrives meanwhile), then prints:

* first paint: from the click on Edit to two animation frames after the network is drawn;
* zoom: frames per second while a wheel event is sent on every animation frame for 2 s;
* pan: the same with a drag of the background;
* all routed: from the click on Edit until every connection is routed (a group of more
  than 300 boxes is drawn first with a quick layout, routing the connections near the view
  before the first paint and the rest while the page idles);
* elkjs layout: from the click on Edit until elkjs's layout of a group of more than 300
  boxes, computed in a Web Worker, replaces the quick one (the figures of zoom and pan are
  taken after it);
* routes: the time to route every connection of the group around the boxes anew in one go
  (what a group with stored positions would cost if it were all routed before the first
  paint); after a drag step: the time to find the routes again after a box in view moved
  by 10 units (its own and nearby connections are routed anew), what each pointer move of
  a drag costs besides drawing.

Goals (issue 16): first paint under 1 s; pan and zoom at 60 frames/s. Headless Chromium
draws in software, so a busy machine gives lower figures than a desktop browser.
"""
from __future__ import annotations

import os
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "ikaros", "webui", "tests"))

import models  # noqa: E402
from browsing import ARGS, CHROMIUM, Server  # noqa: E402
from playwright.sync_api import sync_playwright  # noqa: E402

GESTURE = """async (kind) => {
    const svg = document.querySelector('#editor-host svg.network-view');
    const r = svg.getBoundingClientRect();
    const at = (x, y) => ({clientX: x, clientY: y, bubbles: true, cancelable: true, button: 0, pointerId: 1});
    const x0 = r.x + 40, y0 = r.y + r.height - 10;
    if (kind === 'pan') document.elementFromPoint(x0, y0).dispatchEvent(new PointerEvent('pointerdown', at(x0, y0)));
    let frames = 0, worst = 0; const t0 = performance.now(); let last = t0;
    await new Promise((done) => {
        const step = (t) => {
            frames++; worst = Math.max(worst, t - last); last = t;
            if (kind === 'zoom') svg.dispatchEvent(new WheelEvent('wheel', {...at(r.x + r.width / 2, r.y + r.height / 2), deltaY: frames % 20 < 10 ? -40 : 40}));
            else window.dispatchEvent(new PointerEvent('pointermove', at(x0 + 3 * (frames % 100), y0 - 2 * (frames % 100))));
            if (t - t0 < 2000) requestAnimationFrame(step); else done();
        };
        requestAnimationFrame(step);
    });
    if (kind === 'pan') window.dispatchEvent(new PointerEvent('pointerup', at(x0, y0)));
    return [frames / ((performance.now() - t0) / 1000), worst];
}"""


# the routes after one step of a drag: a box in view 10 units down, 20 times
MOVE = """() => {
    const e = window.ikaros.editor, v = e.netView.visible(0);
    const movable = e.graph.boxes.filter((b) => b.kind === 'module' || b.kind === 'group');
    const b = movable.find((b) => { const p = e.positions.get(b.key); return p.x > v[0] && p.y > v[1]; }) || movable[0];
    const p0 = e.positions.get(b.key), t = performance.now();
    for (let i = 1; i <= 20; i++) { e.positions.set(b.key, {x: p0.x, y: p0.y + 10 * i}); e.currentRoutes(); }
    const ms = (performance.now() - t) / 20;
    e.positions.set(b.key, p0);
    e.redraw();
    return ms;
}"""


def measure(model: str) -> None:
    server = Server(model)
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
            page = browser.new_page(viewport={"width": 1400, "height": 900})
            page.goto(server.base + "/")
            page.wait_for_function("() => window.ikaros && window.ikaros.socket.connected")
            page.wait_for_timeout(2500)
            page.evaluate("() => window.ikaros.editor.loadClasses()")
            t0 = time.perf_counter()
            page.click("#toggle-editor")
            page.wait_for_selector("#editor-host[data-ready] svg.network-view", timeout=120_000)
            page.evaluate("() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)))")
            paint = (time.perf_counter() - t0) * 1000
            boxes = page.evaluate("() => window.ikaros.editor.graph.boxes.length")
            drawn = page.evaluate("() => document.querySelectorAll('#editor-host rect.box').length")
            page.wait_for_function("() => !window.ikaros.editor.routing?.pending.length", timeout=120_000)
            routed = (time.perf_counter() - t0) * 1000
            page.wait_for_selector("#editor-host:not([data-layout='quick'])", timeout=120_000)
            laid_out = (time.perf_counter() - t0) * 1000
            page.wait_for_function("() => !window.ikaros.editor.routing?.pending.length", timeout=120_000)
            routes, route_ms = page.evaluate("""() => { const e = window.ikaros.editor; e.routing = null;
                const keeper = e.routesOfGroup(), t = performance.now();
                const r = keeper.routesFor(e.graph, e.positions); return [r.size, performance.now() - t]; }""")
            move_ms = page.evaluate(MOVE)
            zoom, zoom_worst = page.evaluate(GESTURE, "zoom")
            page.wait_for_timeout(500)
            pan, pan_worst = page.evaluate(GESTURE, "pan")
            browser.close()
    finally:
        server.stop()
    print(f"{os.path.basename(model):20} {boxes:5d} boxes ({drawn:4d} drawn)  first paint "
          f"{paint:5.0f} ms  "
          f"zoom {zoom:5.1f} frames/s (worst {zoom_worst:4.0f} ms)  "
          f"pan {pan:5.1f} frames/s (worst {pan_worst:4.0f} ms)  "
          f"all routed after {routed:5.0f} ms  elkjs layout after {laid_out:5.0f} ms  "
          f"routes {routes:4d} in {route_ms:4.0f} ms at once, after a drag step {move_ms:4.1f} ms")


def skip_chain(folder: str, n: int) -> str:
    """A flat group of ``n`` modules in a chain, each also fed by the module four places
    back: connections that must go around the boxes they pass. Returns the file's path."""
    lines = ['<?xml version="1.0"?>', f'<group name="SkipChain{n}">',
             '    <module class="Constant" name="M0" data="1" />']
    lines += [f'    <module class="Add" name="M{i}" />' for i in range(1, n)]
    for i in range(1, n):
        lines.append(f'    <connection source="M{i - 1}.OUTPUT" target="M{i}.INPUT1" />')
        lines.append(f'    <connection source="M{max(0, i - 4)}.OUTPUT" target="M{i}.INPUT2" />')
    path = os.path.join(folder, f"skip_chain_{n}.ikg")
    with open(path, "w") as f:
        f.write("\n".join(lines + ["</group>", ""]))
    return path


def main() -> None:
    with tempfile.TemporaryDirectory() as folder:
        for model in (models.robot_320(folder), models.chain(folder, 320),
                      models.chain(folder, 2000), skip_chain(folder, 2000)):
            measure(model)


if __name__ == "__main__":
    main()
