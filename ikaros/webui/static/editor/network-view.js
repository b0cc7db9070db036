// The network view of one group: SVG boxes with input ports on the left and output ports on
// the right, connections (routed by the owner, else curves) labelled with their delay, the group's inputs and outputs
// as pins at the edges. Zoom (wheel), pan (drag the background), select (click, shift-click,
// or a rubber band: shift- or alt-drag on the background),
// move (drag boxes by their title), connect (drag from an output port, its name or its row
// to an input port, or the other way round), open a group
// (double-click). The view changes nothing itself: it reports to its owner.
import { HEADER, PORT_H, edgeKey, portOffset } from "./layout.js";

const SVG = "http://www.w3.org/2000/svg";
const MIN_ZOOM = 0.02;   // a group of thousands of modules still fits the view
const REST_MS = 150;     // a pan or zoom gesture is drawn anew after this long at rest
const CULL_LIMIT = 400;  // boxes; a bigger group is drawn only around the view
const OVERVIEW_ZOOM = 0.3;  // below it a bigger group is drawn as an overview (isOverview)

const overlaps = (a, b) => a[0] < b[2] && a[2] > b[0] && a[1] < b[3] && a[3] > b[1];
const inside = (a, b) => a[0] >= b[0] && a[1] >= b[1] && a[2] <= b[2] && a[3] <= b[3];

function el(tag, attrs = {}, parent = null) {
    const e = document.createElementNS(SVG, tag);
    for (const [k, v] of Object.entries(attrs)) if (v !== undefined && v !== null) e.setAttribute(k, v);
    if (parent) parent.appendChild(e);
    return e;
}

/** The control points of a connection's curve; a backward one loops below its ends. */
function controls(x1, y1, x2, y2) {
    const back = x2 < x1 + 30;
    const dx = back ? Math.max(80, (x1 - x2) / 2) : Math.max(40, Math.abs(x2 - x1) / 2);
    const dy = back ? 50 + Math.abs(y2 - y1) / 4 : 0;
    return [[x1, y1], [x1 + dx, y1 + dy], [x2 - dx, y2 + dy], [x2, y2]];
}

function curve(x1, y1, x2, y2) {
    const [a, b, c, d] = controls(x1, y1, x2, y2);
    return `M${a} C${b} ${c} ${d}`;
}

/** The point at t (0..1) of the curve. */
function pointAt(x1, y1, x2, y2, t) {
    const [a, b, c, d] = controls(x1, y1, x2, y2);
    const u = 1 - t;
    return [0, 1].map((i) => u * u * u * a[i] + 3 * u * u * t * b[i] + 3 * u * t * t * c[i] + t * t * t * d[i]);
}

/** The point at fraction t of a polyline's length. */
function alongPolyline(pts, t) {
    const lengths = pts.slice(1).map((p, i) => Math.hypot(p[0] - pts[i][0], p[1] - pts[i][1]));
    let rest = t * lengths.reduce((a, b) => a + b, 0);
    for (let i = 0; i < lengths.length; i++) {
        if (rest <= lengths[i] || i === lengths.length - 1) {
            const f = lengths[i] ? Math.min(1, rest / lengths[i]) : 0;
            return [pts[i][0] + f * (pts[i + 1][0] - pts[i][0]), pts[i][1] + f * (pts[i + 1][1] - pts[i][1])];
        }
        rest -= lengths[i];
    }
    return pts[0];
}

// Where a label may sit along its connection, best first: the middle, then out to the ends.
const LABEL_T = [0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.12, 0.88];
const CELL = 64;      // the grid cell of the label placer (drawing units)

/** Rectangles indexed by grid cell, to find overlaps among thousands quickly. */
class RectGrid {
    constructor() { this.cells = new Map(); }
    *keys([x0, y0, x1, y1]) {
        for (let i = Math.floor(x0 / CELL); i <= Math.floor(x1 / CELL); i++)
            for (let j = Math.floor(y0 / CELL); j <= Math.floor(y1 / CELL); j++) yield i + "," + j;
    }
    add(r) { for (const k of this.keys(r)) { if (!this.cells.has(k)) this.cells.set(k, []); this.cells.get(k).push(r); } }
    /** The area of r covered by the rectangles stored. */
    overlap(r) {
        let area = 0;
        const seen = new Set();
        for (const k of this.keys(r)) {
            for (const q of this.cells.get(k) || []) {
                if (seen.has(q)) continue;
                seen.add(q);
                const w = Math.min(r[2], q[2]) - Math.max(r[0], q[0]), h = Math.min(r[3], q[3]) - Math.max(r[1], q[1]);
                if (w > 0 && h > 0) area += w * h;
            }
        }
        return area;
    }
}

export class NetworkView {
    /**
     * handlers: onSelect(nodes, additive), onOpenGroup(name), onMove(Map key -> {x, y}),
     * onConnect(from {box, port}, to {box, port}), onBand(box keys, additive),
     * onTogglePorts(box key), routes() (the connections' routes while boxes are dragged)
     */
    constructor(host, handlers) {
        this.host = host;
        this.h = handlers;
        this.svg = el("svg", { class: "network-view", tabindex: "0" });
        host.appendChild(this.svg);
        this.root = el("g", { class: "viewport" }, this.svg);
        this.t = { k: 1, x: 0, y: 0 };
        this.graph = null;
        this.pos = new Map();
        this.drag = null;
        this.svg.addEventListener("wheel", (e) => this.onWheel(e), { passive: false });
        this.svg.addEventListener("pointerdown", (e) => this.onDown(e));
        window.addEventListener("pointermove", (e) => this.onMoveEvent(e));
        window.addEventListener("pointerup", (e) => this.onUp(e));
        this.svg.addEventListener("dblclick", (e) => {
            const g = e.target.closest?.("[data-key]");
            const b = g && this.graph?.boxes.find((x) => x.key === g.dataset.key);
            if (b && b.kind === "group") this.h.onOpenGroup(b.name);
        });
    }

    destroy() { this.svg.remove(); }

    setTransform(t) {
        clearTimeout(this.settle);
        this.t = { ...t };
        this.committed = { ...this.t };
        this.svg.style.transform = "";
        this.root.setAttribute("transform", `translate(${this.t.x},${this.t.y}) scale(${this.t.k})`);
        // level of detail: small text is left out when it could not be read anyway
        this.svg.classList.toggle("far", this.t.k < 0.5);
        this.svg.classList.toggle("very-far", this.t.k < 0.3);
        // a big group is drawn only around the view: draw again when the view leaves it, or
        // when it is zoomed across the overview's threshold
        if ((this.drawn && !inside(this.visible(0), this.drawn)) ||
            (this.graph && this.overview !== this.isOverview())) this.draw();
    }

    /** Whether a big group is drawn as an overview at this zoom: boxes and lines only (no
     *  ports, names or badges, which are too small to see: they would only cost time). */
    isOverview() { return this.graph.boxes.length > CULL_LIMIT && this.t.k < OVERVIEW_ZOOM; }

    /** The part of the drawing in view, widened by ``margin`` views on each side. */
    visible(margin) {
        const r = this.svg.getBoundingClientRect();
        const w = (r.width || 800) / this.t.k, h = (r.height || 600) / this.t.k;
        const x = -this.t.x / this.t.k, y = -this.t.y / this.t.k;
        return [x - margin * w, y - margin * h, x + (1 + margin) * w, y + (1 + margin) * h];
    }

    /** A transform during a wheel or a drag: the drawing already painted is moved and
     *  scaled as one layer by the compositor (the SVG is not drawn again, so big groups
     *  pan and zoom smoothly); it is drawn at the new transform once the gesture rests. */
    gesture(t) {
        const c = this.committed || this.t;
        this.t = { ...t };
        const f = t.k / c.k;
        this.svg.style.transform = `translate(${t.x - f * c.x}px, ${t.y - f * c.y}px) scale(${f})`;
        clearTimeout(this.settle);
        this.settle = setTimeout(() => this.setTransform(this.t), REST_MS);
    }

    /** The drawing's extent [x0, y0, x1, y1]: every box (with room for an error note
     *  under it) and every connection, routed or curved (a feedback loop goes around the
     *  boxes), with its delay badge. */
    extent() {
        let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
        const add = (x, y, mx = 0, my = 0) => {
            x0 = Math.min(x0, x - mx); y0 = Math.min(y0, y - my);
            x1 = Math.max(x1, x + mx); y1 = Math.max(y1, y + my);
        };
        for (const b of this.graph.boxes) {
            const p = this.pos.get(b.key);
            if (!p) continue;
            add(p.x, p.y);
            add(p.x + b.w, p.y + b.h + 30);
        }
        for (const e of this.graph.edges) {
            if (!e.from.box || !e.to.box || !this.pos.get(e.from.box.key) || !this.pos.get(e.to.box.key)) continue;
            const route = this.routes?.get(edgeKey(e));
            if (route) { for (const [x, y] of route) add(x, y, 4, 4); continue; }
            const a = this.portXY(e.from.box, "out", e.from.port), b = this.portXY(e.to.box, "in", e.to.port);
            for (let i = 0; i <= 20; i++) add(...pointAt(a.x, a.y, b.x, b.y, i / 20), 4, 4);
        }
        for (const L of this.labels || []) {
            const r = L.placed;
            if (r) { add(r[0], r[1]); add(r[2], r[3]); }
        }
        return [x0, y0, x1, y1];
    }

    /** Pan as little as it takes (at this zoom) to bring the rectangle x, y, w, h of the
     *  drawing into the view, 20 px from its edges. */
    reveal(x, y, w, h) {
        const r = this.svg.getBoundingClientRect();
        const { k } = this.t;
        const shift = (lo, hi, size) => (lo < 20 || hi - lo > size - 40) ? 20 - lo : hi > size - 20 ? size - 20 - hi : 0;
        const dx = shift(x * k + this.t.x, (x + w) * k + this.t.x, r.width || 800);
        const dy = shift(y * k + this.t.y, (y + h) * k + this.t.y, r.height || 600);
        if (dx || dy) this.setTransform({ k, x: this.t.x + dx, y: this.t.y + dy });
    }

    /** Fit the drawing into the view. */
    fit() {
        if (!this.graph || !this.graph.boxes.length) { this.setTransform({ k: 1, x: 20, y: 20 }); return; }
        const r = this.svg.getBoundingClientRect();
        const [x0, y0, x1, y1] = this.extent();
        const w = Math.max(1, r.width || 800), h = Math.max(1, r.height || 600);
        // as far out as it takes to show everything (text too small to read is left out)
        const k = Math.min(1.25, Math.max(MIN_ZOOM, Math.min((w - 40) / (x1 - x0 + 1), (h - 40) / (y1 - y0 + 1))));
        this.setTransform({ k, x: 20 - x0 * k, y: 20 - y0 * k });
    }

    zoom(factor, cx = null, cy = null, gesture = false) {
        const r = this.svg.getBoundingClientRect();
        if (cx === null) { cx = r.width / 2; cy = r.height / 2; }
        const k = Math.min(4, Math.max(MIN_ZOOM, this.t.k * factor));
        const f = k / this.t.k;
        const t = { k, x: cx - (cx - this.t.x) * f, y: cy - (cy - this.t.y) * f };
        if (gesture) this.gesture(t); else this.setTransform(t);
    }

    onWheel(e) {
        e.preventDefault();
        const r = this.svg.getBoundingClientRect();
        this.zoom(Math.exp(-e.deltaY * 0.0015), e.clientX - r.left, e.clientY - r.top, true);
    }

    /** Screen point to drawing coordinates. */
    local(e) {
        const r = this.svg.getBoundingClientRect();
        return { x: (e.clientX - r.left - this.t.x) / this.t.k, y: (e.clientY - r.top - this.t.y) / this.t.k };
    }

    // --- drawing -------------------------------------------------------------------------

    /** Draw a graph: positions Map(key -> {x, y}); errors Map(node -> message); selection Set(node). */
    show(graph, positions, { errors = new Map(), selection = new Set(), groupError = null, routes = new Map() } = {}) {
        this.graph = graph;
        this.routes = routes;
        this.pos = positions;
        this.errors = errors;
        this.selection = selection;
        this.groupError = groupError;
        this.draw();
    }

    /** Draw the graph; a group of more than CULL_LIMIT boxes only within a view around the
     *  one on screen (the rest is drawn when panned or zoomed to). */
    draw() {
        const { graph, groupError } = this;
        this.drawn = graph.boxes.length > CULL_LIMIT ? this.visible(1) : null;
        this.overview = this.isOverview();
        const shown = (b) => {
            if (!this.drawn) return true;
            const p = this.pos.get(b.key);
            return p && overlaps([p.x, p.y, p.x + b.w, p.y + b.h], this.drawn);
        };
        const drawnBoxes = new Set(graph.boxes.filter(shown));
        this.root.textContent = "";
        this.svg.querySelectorAll(":scope > .group-error").forEach((x) => x.remove());
        const edgeLayer = el("g", { class: "edges" }, this.root);
        const boxLayer = el("g", { class: "boxes" }, this.root);
        const labelLayer = el("g", { class: "edge-labels" }, this.root);
        this.tempLayer = el("g", { class: "temp" }, this.root);
        for (const b of drawnBoxes) this.drawBox(boxLayer, b);
        this.labels = [];
        if (this.overview) this.drawLines(edgeLayer);
        else {
            graph.edges.forEach((e, i) => {
                if (drawnBoxes.has(e.from.box) || drawnBoxes.has(e.to.box)) this.drawEdge(edgeLayer, labelLayer, e, i);
            });
            this.placeLabels(labelLayer);
        }
        if (groupError) {
            const f = el("foreignObject", { x: 8, y: 8, width: 600, height: 80, class: "group-error" }, this.svg);
            const d = document.createElement("div");
            d.className = "editor-error";
            d.textContent = groupError;
            f.appendChild(d);
        }
    }

    portXY(b, side, port) {
        const p = this.pos.get(b.key) || { x: 0, y: 0 };
        const o = portOffset(b, side, port);
        return { x: p.x + o.x, y: p.y + o.y };
    }

    drawBox(layer, b) {
        const p = this.pos.get(b.key) || { x: 0, y: 0 };
        const selected = b.node && this.selection.has(b.node);
        const error = b.node && this.errors.get(b.node);
        const g = el("g", { class: `box-group kind-${b.kind}${selected ? " selected" : ""}${error ? " has-error" : ""}${b.readOnly ? " read-only" : ""}`,
            "data-key": b.key, "data-name": b.name, "data-kind": b.kind, transform: `translate(${p.x},${p.y})` }, layer);
        el("rect", { class: "box", width: b.w, height: b.h, rx: b.kind === "module" || b.kind === "group" ? 5 : 13,
            "data-name": b.name, "data-kind": b.kind }, g);
        if (this.overview) return;
        if (b.kind === "module" || b.kind === "group") {
            el("line", { class: "box-rule", x1: 0, y1: HEADER - 4, x2: b.w, y2: HEADER - 4 }, g);
            const name = el("text", { class: "box-name", x: b.w / 2, y: 15, "text-anchor": "middle" }, g);
            name.textContent = b.name;
            const cls = el("text", { class: "box-class", x: b.w / 2, y: 29, "text-anchor": "middle" }, g);
            cls.textContent = b.kind === "group" ? "group ▸" : b.label + (b.unknown ? " (unknown class)" : "");
            if (b.collapsible) {
                // show or hide the ports no connection uses
                const tg = el("g", { class: "port-toggle", "data-key": b.key, role: "button", tabindex: "0",
                    "aria-label": b.expanded ? `hide the unused ports of ${b.name}` : `show all ${b.hidden} hidden ports of ${b.name}` }, g);
                el("rect", { x: b.w - 34, y: 3, width: 30, height: 14, rx: 7 }, tg);
                const t = el("text", { x: b.w - 19, y: 14, "text-anchor": "middle" }, tg);
                t.textContent = b.expanded ? "−" : `+${b.hidden}`;
                const tip = el("title", {}, tg);
                tip.textContent = b.expanded ? "hide the unused ports" : `${b.hidden} unused ports: show them`;
            }
        } else {
            const t = el("text", { class: "box-name", x: b.w / 2, y: b.h / 2 + 4, "text-anchor": "middle" }, g);
            t.textContent = (b.kind.startsWith("external") ? "⋯ " : "") + b.name;
        }
        for (const side of ["in", "out"]) {
            for (const port of side === "in" ? b.inputs : b.outputs) {
                const o = portOffset(b, side, port);
                const pg = el("g", { class: `port port-${side}`, "data-port": port, "data-side": side, "data-key": b.key }, g);
                // the circle and the name start a connection; the box is moved by its title
                // and the rest of its body
                const named = port && (b.kind === "module" || b.kind === "group");
                const reach = named ? Math.min(b.w / 2, 14 + 6.2 * port.length) : 8;
                el("rect", { class: "port-hit", x: side === "in" ? o.x - 8 : o.x - reach, y: o.y - PORT_H / 2,
                    width: reach + 8, height: PORT_H }, pg);
                el("circle", { cx: o.x, cy: o.y, r: 5 }, pg);
                if (port && (b.kind === "module" || b.kind === "group")) {
                    const t = el("text", { class: "port-name", x: side === "in" ? o.x + 9 : o.x - 9, y: o.y + 4,
                        "text-anchor": side === "in" ? "start" : "end" }, pg);
                    t.textContent = port;
                }
            }
        }
        const title = el("title", {}, g);
        title.textContent = b.kind === "module" ? `${b.name} (${b.label})` : `${b.name} (${b.kind})`;
        if (error) this.errorNote(layer, p.x, p.y + b.h + 4, error);
    }

    errorNote(layer, x, y, message) {
        const f = el("foreignObject", { x, y, width: 280, height: 90, class: "error-note" }, layer);
        const d = document.createElement("div");
        d.className = "editor-error";
        d.textContent = message;
        f.appendChild(d);
    }

    /** The overview's connections: one path of them all, as routed or curved. */
    drawLines(layer) {
        const parts = [];
        for (const e of this.graph.edges) {
            if (!e.from.box || !e.to.box || !this.pos.get(e.from.box.key) || !this.pos.get(e.to.box.key)) continue;
            const route = this.routes.get(edgeKey(e));
            if (route) { parts.push("M" + route.map((p) => p.join(",")).join(" L")); continue; }
            const a = this.portXY(e.from.box, "out", e.from.port), b = this.portXY(e.to.box, "in", e.to.port);
            parts.push(curve(a.x, a.y, b.x, b.y));
        }
        el("path", { class: "edge-line overview-lines", d: parts.join(" ") }, el("g", { class: "edge" }, layer));
    }

    drawEdge(layer, labels, e, i) {
        if (!e.from.box || !e.to.box) return;
        const a = this.portXY(e.from.box, "out", e.from.port);
        const b = this.portXY(e.to.box, "in", e.to.port);
        const selected = this.selection.has(e.node);
        const error = this.errors.get(e.node);
        const g = el("g", { class: `edge${selected ? " selected" : ""}${error ? " has-error" : ""}${e.outputSource ? " output-source" : ""}`,
            "data-edge": String(i), "data-source": e.node.attrs.source || "", "data-target": e.node.attrs.target || e.node.attrs.name || "" }, layer);
        // routed around the boxes (orthogonal: elkjs's routes, or the editor's once a box moved)
        const route = this.routes.get(edgeKey(e));
        const d = route ? "M" + route.map((p) => p.join(",")).join(" L") : curve(a.x, a.y, b.x, b.y);
        if (route) g.classList.add("routed");
        el("path", { class: "edge-hit", d }, g);
        el("path", { class: "edge-line", d }, g);
        const label = [e.delay, e.from.selector, e.to.selector ? "→" + e.to.selector : ""].filter(Boolean).join(" ");
        const at = route ? (t) => alongPolyline(route, t) : (t) => pointAt(a.x, a.y, b.x, b.y, t);
        if (label) this.labels.push({ text: label, i, selected, error, e, at });
        else if (error) { const [mx, my] = at(0.5); this.errorNote(labels, mx - 20, my + 12, error); }
    }

    /** Put every connection's label (its delay badge) on its own curve where it overlaps
     *  no other label and no box: the middle when free, else the free place nearest to it,
     *  else the place of least overlap. */
    placeLabels(layer) {
        const taken = new RectGrid();
        for (const b of this.graph.boxes) {
            const p = this.pos.get(b.key);
            if (p) taken.add([p.x, p.y, p.x + b.w, p.y + b.h]);
        }
        for (const L of this.labels) {
            const w = 8 + 7 * L.text.length, hh = 9;
            let best = null;
            for (const t of LABEL_T) {
                const [x, y] = L.at(t);
                const r = [x - w / 2, y - hh, x + w / 2, y + hh];
                const cost = taken.overlap(r);
                if (!best || cost < best.cost) best = { x, y, r, cost };
                if (cost === 0) break;
            }
            taken.add(best.r);
            L.placed = best.r;
            const { x: mx, y: my } = best;
            const lg = el("g", { class: `edge-label${L.selected ? " selected" : ""}`, "data-edge": String(L.i) }, layer);
            el("rect", { x: mx - w / 2, y: my - hh, width: w, height: 2 * hh, rx: hh }, lg);
            const t = el("text", { x: mx, y: my + 4, "text-anchor": "middle" }, lg);
            t.textContent = L.text;
            const title = el("title", {}, lg);
            title.textContent = `${L.e.node.attrs.source} → ${L.e.node.attrs.target}, delay ${L.e.delay}`;
            if (L.error) this.errorNote(layer, mx - 20, my + 12, L.error);
        }
    }

    // --- interaction ---------------------------------------------------------------------

    onDown(e) {
        if (e.button !== 0) return;
        this.svg.focus({ preventScroll: true });
        const toggle = e.target.closest?.(".port-toggle");
        if (toggle) {
            this.h.onTogglePorts?.(toggle.dataset.key);
            e.preventDefault();
            return;
        }
        const port = e.target.closest?.(".port");
        const boxEl = e.target.closest?.(".box-group");
        const edgeEl = e.target.closest?.("[data-edge]");
        const start = { cx: e.clientX, cy: e.clientY };
        if (port) {
            // from an output to an input, or the other way round
            const b = this.graph.boxes.find((x) => x.key === port.dataset.key);
            const side = port.dataset.side;
            if (b && (!b.readOnly || (side === "out" && b.kind === "input") || (side === "in" && b.kind === "output"))) {
                const from = this.portXY(b, side, port.dataset.port);
                this.drag = { kind: "connect", side, end: { box: b, port: port.dataset.port }, start: from,
                    path: el("path", { class: "edge-temp", d: curve(from.x, from.y, from.x, from.y) }, this.tempLayer) };
                this.svg.classList.add(side === "out" ? "connecting-to-in" : "connecting-to-out");
                e.preventDefault();
                return;
            }
        }
        if (boxEl) {
            const b = this.graph.boxes.find((x) => x.key === boxEl.dataset.key);
            if (!b?.node) return;
            if (!this.selection.has(b.node) || e.shiftKey) this.h.onSelect([b.node], e.shiftKey);
            const movable = this.graph.boxes.filter((x) => x.node && this.selection.has(x.node) && (x.kind === "module" || x.kind === "group") && !x.readOnly);
            this.drag = { kind: "move", ...start, boxes: movable.map((x) => ({ b: x, p0: { ...this.pos.get(x.key) } })), moved: false };
            e.preventDefault();
            return;
        }
        if (edgeEl) {
            const edge = this.graph.edges[+edgeEl.dataset.edge];
            if (edge) this.h.onSelect([edge.node], e.shiftKey);
            return;
        }
        if (e.shiftKey || e.altKey) {          // a rubber band selects the boxes it touches
            const p = this.local(e);
            this.drag = { kind: "band", p0: p, additive: e.shiftKey,
                rect: el("rect", { class: "rubber-band", x: p.x, y: p.y, width: 0, height: 0 }, this.tempLayer) };
            e.preventDefault();
            return;
        }
        this.drag = { kind: "pan", ...start, t0: { ...this.t }, moved: false };
    }

    /** The keys of the boxes that a rectangle in drawing coordinates touches. */
    boxesIn(x0, y0, x1, y1) {
        return this.graph.boxes.filter((b) => {
            const p = this.pos.get(b.key);
            return p && p.x < x1 && p.x + b.w > x0 && p.y < y1 && p.y + b.h > y0;
        }).map((b) => b.key);
    }

    onMoveEvent(e) {
        const d = this.drag;
        if (!d) return;
        if (d.kind === "pan") {
            const dx = e.clientX - d.cx, dy = e.clientY - d.cy;
            if (Math.abs(dx) + Math.abs(dy) > 2) d.moved = true;
            this.gesture({ k: d.t0.k, x: d.t0.x + dx, y: d.t0.y + dy });
        } else if (d.kind === "move") {
            const dx = (e.clientX - d.cx) / this.t.k, dy = (e.clientY - d.cy) / this.t.k;
            if (Math.abs(dx) + Math.abs(dy) > 2) d.moved = true;
            if (!d.moved) return;
            for (const { b, p0 } of d.boxes) {
                const p = { x: Math.round((p0.x + dx) / 10) * 10, y: Math.round((p0.y + dy) / 10) * 10 };
                this.pos.set(b.key, p);
            }
            this.show(this.graph, this.pos, { errors: this.errors, selection: this.selection, routes: this.h.routes?.() });
        } else if (d.kind === "band") {
            const p = this.local(e);
            d.box = [Math.min(p.x, d.p0.x), Math.min(p.y, d.p0.y), Math.max(p.x, d.p0.x), Math.max(p.y, d.p0.y)];
            const [x0, y0, x1, y1] = d.box;
            for (const [k, v] of Object.entries({ x: x0, y: y0, width: x1 - x0, height: y1 - y0 })) d.rect.setAttribute(k, v);
        } else if (d.kind === "connect") {
            const p = this.local(e);
            d.path.setAttribute("d", d.side === "out" ? curve(d.start.x, d.start.y, p.x, p.y) : curve(p.x, p.y, d.start.x, d.start.y));
            const over = this.connectTarget(d, e);
            this.svg.querySelectorAll(".port.target").forEach((x) => x.classList.remove("target"));
            if (over) over.classList.add("target");
        }
    }

    onUp(e) {
        const d = this.drag;
        this.drag = null;
        if (!d) return;
        if (d.kind === "pan" && d.moved) this.setTransform(this.t);
        if (d.kind === "band") {
            d.rect.remove();
            if (d.box) this.h.onBand?.(this.boxesIn(...d.box), d.additive);
        }
        if (d.kind === "pan" && !d.moved) this.h.onSelect([], false);
        if (d.kind === "move" && d.moved) this.h.onMove(new Map(d.boxes.map(({ b }) => [b.key, this.pos.get(b.key)])));
        if (d.kind === "connect") {
            d.path.remove();
            this.svg.classList.remove("connecting-to-in", "connecting-to-out");
            this.svg.querySelectorAll(".port.target").forEach((x) => x.classList.remove("target"));
            const over = this.connectTarget(d, e);
            const b = over && this.graph.boxes.find((x) => x.key === over.dataset.key);
            if (b) {
                const other = { box: b, port: over.dataset.port };
                if (d.side === "out") this.h.onConnect(d.end, other); else this.h.onConnect(other, d.end);
            }
        }
    }

    /** The port of the other kind under the pointer while connecting, or null. */
    connectTarget(d, e) {
        return document.elementFromPoint(e.clientX, e.clientY)?.closest?.(d.side === "out" ? ".port-in" : ".port-out") || null;
    }
}
