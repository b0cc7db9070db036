// A group as a graph of boxes and edges, box geometry, and the automatic layout (elkjs,
// layered, left to right along the data flow) for groups whose file gives no _x, _y.
import { kids, elements, splitAddress } from "./model.js";

export const ELK_LIMIT = 300;   // boxes; a bigger group is drawn first with simpleLayout
const PACK_LIMIT = 50;          // boxes; a bigger group is packed to the view's shape (packParts)
const KEPT_LAYOUTS = 4;         // elkjs layouts of big groups kept for when they are shown again
export const BOX_W = 170, HEADER = 38, PORT_H = 18, PIN_W = 120, PIN_H = 26;

/**
 * The graph of a group node: boxes (modules, subgroups; the group's inputs, outputs and
 * addresses outside the group as pins at the edges) and edges (connections, and the sources
 * of group outputs). classes: {name: description} from /api/classes. A subgroup shows only
 * its connected ports unless its key is in ``expanded``; ``hidden`` counts the others.
 */
export function graphOf(g, classes = {}, expanded = new Set()) {
    const boxes = new Map();
    const add = (b) => { boxes.set(b.key, b); return b; };
    for (const { node, readOnly } of elements(g)) {
        if (node.tag === "module") {
            const desc = classes[node.attrs.class] || null;
            add({ key: "c:" + node.attrs.name, kind: "module", node, readOnly, name: node.attrs.name,
                label: node.attrs.class || "?", inputs: (desc?.inputs || []).map((i) => i.name),
                outputs: (desc?.outputs || []).map((o) => o.name), unknown: !desc });
        } else if (node.tag === "group") {
            add({ key: "c:" + node.attrs.name, kind: "group", node, readOnly, name: node.attrs.name, label: "group",
                inputs: kids(node, "input").map((i) => i.attrs.name).filter(Boolean),
                outputs: kids(node, "output").map((o) => o.attrs.name).filter(Boolean) });
        } else if (node.tag === "input" && node.attrs.name) {
            add({ key: "i:" + node.attrs.name, kind: "input", node, readOnly, name: node.attrs.name, label: "input", inputs: [], outputs: [""] });
        } else if (node.tag === "output" && node.attrs.name) {
            add({ key: "o:" + node.attrs.name, kind: "output", node, readOnly, name: node.attrs.name, label: "output", inputs: [""], outputs: [] });
        }
    }
    const edges = [];
    const end = (text, role) => {
        const a = splitAddress(text);
        const p = a.parts;
        const child = boxes.get("c:" + p[0]);
        if (a.path && !a.path.startsWith(".") && child && p.length >= 2) {
            const port = p.slice(1).join(".");
            const list = role === "source" ? child.outputs : child.inputs;
            if (!list.includes(port)) list.push(port);
            return { box: child, port, selector: a.selector };
        }
        if (p.length === 1 && p[0]) {
            const pin = boxes.get((role === "source" ? "i:" : "o:") + p[0]);
            if (pin) return { box: pin, port: "", selector: a.selector };
        }
        // an address outside the group: a pin of its own at the edge
        const key = "x:" + role + ":" + a.path;
        const pin = boxes.get(key) || add({ key, kind: role === "source" ? "external-in" : "external-out", node: null,
            readOnly: true, name: a.path || "?", label: "outside", inputs: role === "source" ? [] : [""], outputs: role === "source" ? [""] : [] });
        return { box: pin, port: "", selector: a.selector };
    };
    for (const { node, readOnly } of elements(g, "connection")) {
        const from = end(node.attrs.source, "source");
        const to = end(node.attrs.target, "target");
        edges.push({ node, readOnly, from, to, delay: node.attrs.delay ?? "1" });
    }
    for (const { node } of elements(g, "output")) {
        if (!node.attrs.source || !node.attrs.name) continue;
        const from = end(node.attrs.source, "source");
        edges.push({ node, readOnly: true, outputSource: true, from, to: { box: boxes.get("o:" + node.attrs.name), port: "" }, delay: "" });
    }
    collapsePorts(boxes, edges, expanded);
    for (const b of boxes.values()) Object.assign(b, size(b));
    return { boxes: [...boxes.values()], edges };
}

/** Subgroups show only the ports a connection uses, unless expanded: a group's inside is
 *  not the business of the group around it. */
function collapsePorts(boxes, edges, expanded) {
    for (const b of boxes.values()) {
        if (b.kind !== "group") continue;
        const used = { in: new Set(), out: new Set() };
        for (const e of edges) {
            if (e.from.box === b) used.out.add(e.from.port);
            if (e.to.box === b) used.in.add(e.to.port);
        }
        const all = b.inputs.length + b.outputs.length;
        b.expanded = expanded.has(b.key);
        if (!b.expanded) {
            b.inputs = b.inputs.filter((p) => used.in.has(p));
            b.outputs = b.outputs.filter((p) => used.out.has(p));
        }
        b.hidden = all - b.inputs.length - b.outputs.length;
        b.collapsible = all > 0 && (b.expanded ? used.in.size + used.out.size < all : b.hidden > 0);
    }
}

function size(b) {
    if (b.kind === "module" || b.kind === "group") {
        return { w: BOX_W, h: HEADER + Math.max(b.inputs.length, b.outputs.length, 1) * PORT_H + 6 };
    }
    return { w: PIN_W, h: PIN_H };
}

/** Where a port is, relative to its box. */
export function portOffset(b, side, port) {
    if (b.kind !== "module" && b.kind !== "group") return { x: side === "in" ? 0 : b.w, y: b.h / 2 };
    const list = side === "in" ? b.inputs : b.outputs;
    const i = Math.max(0, list.indexOf(port));
    return { x: side === "in" ? 0 : b.w, y: HEADER + i * PORT_H + PORT_H / 2 };
}

const isComponent = (b) => b.kind === "module" || b.kind === "group";

/** A stored position, or null. */
export function storedPosition(b) {
    const a = b.node?.attrs;
    if (!a || a._x === undefined || a._y === undefined) return null;
    const x = parseFloat(a._x), y = parseFloat(a._y);
    return Number.isFinite(x) && Number.isFinite(y) ? { x, y } : null;
}

let elkLoading = null;
/** Load elkjs (the first automatic layout needs it; the editor loads it while the page
 *  idles, so that the editor opens at once). */
export function loadElk() {
    if (window.ELK) return Promise.resolve(window.ELK);
    if (!elkLoading) {
        elkLoading = new Promise((resolve, reject) => {
            const s = document.createElement("script");
            s.src = "/static/vendor/elkjs/elk.bundled.js";
            s.onload = () => resolve(window.ELK);
            s.onerror = () => reject(new Error("elkjs did not load"));
            document.head.appendChild(s);
        });
    }
    return elkLoading;
}

/**
 * Positions for every box of a graph: Map(key -> {x, y}). Stored _x/_y are used when
 * every component has them; otherwise the whole group is laid out automatically, with
 * elkjs's routes (Map edgeKey -> points). Pins (group inputs, outputs, outside addresses) sit
 * at the left and right edges. A group of more than ELK_LIMIT boxes is laid out by
 * simpleLayout at once and by elkjs in a Web Worker: ``later`` is the promise of that
 * layout ({positions, routes}, null when elkjs failed or a newer layout replaced it).
 */
export async function layout(graph, { force = false, aspect = 1.6 } = {}) {
    const comps = graph.boxes.filter(isComponent);
    const stored = new Map(comps.map((b) => [b.key, storedPosition(b)]));
    const manual = !force && comps.length > 0 && comps.every((b) => stored.get(b.key));
    let pos, routes = null, later = null;
    if (manual) {
        pos = new Map(comps.map((b) => [b.key, stored.get(b.key)]));
        placePins(graph, pos);
    } else if (graph.boxes.length > ELK_LIMIT) {
        const sign = signature(graph, aspect), kept = bigLayouts.get(sign);
        if (kept) { pos = new Map(kept.pos); routes = kept.routes; }
        else {
            pos = packParts(graph, simpleLayout(graph, aspect), null, aspect).pos;
            later = elkLayout(graph, layoutInWorker, aspect).then((raw) => {
                const r = packParts(graph, raw.pos, raw.routes, aspect, simpleLayout(graph, aspect));
                bigLayouts.delete(sign);
                bigLayouts.set(sign, r);
                if (bigLayouts.size > KEPT_LAYOUTS) bigLayouts.delete(bigLayouts.keys().next().value);
                return { positions: new Map(r.pos), routes: r.routes };
            }, (e) => {
                if (e.message !== REPLACED) console.warn("elk layout failed, keeping the simple one:", e);
                return null;
            });
        }
    } else {
        try {
            ({ pos, routes } = await elkLayout(graph, async (g) => new (await loadElk())().layout(g), aspect));
            if (graph.boxes.length > PACK_LIMIT) {
                ({ pos, routes } = packParts(graph, pos, routes, aspect, simpleLayout(graph, aspect)));
            }
        } catch (e) {
            console.warn("elk layout failed, using the simple one:", e);
            pos = simpleLayout(graph, aspect);
            if (graph.boxes.length > PACK_LIMIT) pos = packParts(graph, pos, null, aspect).pos;
        }
    }
    return { positions: pos, automatic: !manual, routes, later };
}

const bigLayouts = new Map();   // signature -> elkjs's {pos, routes}, the oldest first

/** What a layout depends on: the boxes with their sizes and ports, the connections and the
 *  shape of the view. */
function signature(graph, aspect) {
    return JSON.stringify([graph.boxes.map((b) => [b.key, b.w, b.h, b.inputs, b.outputs]), graph.edges.map(edgeKey),
        Math.round(aspect * 10)]);
}

const REPLACED = "replaced by a newer layout";
let working = null;             // {worker, reject} of the layout in a Web Worker

/** An elkjs layout computed in a Web Worker (elk-worker.js), started once the page idles
 *  (after the quick layout is painted); one at a time, a newer one replaces the one under way. */
function layoutInWorker(input) {
    if (working) { working.worker?.terminate(); working.reject(new Error(REPLACED)); }
    return new Promise((resolve, reject) => {
        const me = working = { worker: null, reject };
        const start = () => {
            if (working !== me) return;
            const worker = me.worker = new Worker("/static/editor/elk-worker.js");
            const done = () => { worker.terminate(); if (working === me) working = null; };
            worker.onmessage = (e) => { done(); if (e.data.error) reject(new Error(e.data.error)); else resolve(e.data.graph); };
            worker.onerror = (e) => { done(); reject(new Error(e.message || "the layout worker failed")); };
            worker.postMessage(input);
        };
        if (window.requestIdleCallback) requestIdleCallback(start, { timeout: 500 }); else setTimeout(start, 100);
    });
}

function placePins(graph, pos) {
    const comps = graph.boxes.filter(isComponent);
    let minX = 0, maxX = 400, minY = 0;
    if (comps.length) {
        minX = Math.min(...comps.map((b) => pos.get(b.key).x));
        maxX = Math.max(...comps.map((b) => pos.get(b.key).x + b.w));
        minY = Math.min(...comps.map((b) => pos.get(b.key).y));
    }
    const left = graph.boxes.filter((b) => b.kind === "input" || b.kind === "external-in");
    const right = graph.boxes.filter((b) => b.kind === "output" || b.kind === "external-out");
    left.forEach((b, i) => pos.set(b.key, { x: minX - PIN_W - 80, y: minY + i * (PIN_H + 20) }));
    right.forEach((b, i) => pos.set(b.key, { x: maxX + 80, y: minY + i * (PIN_H + 20) }));
}

/** What names a connection across layouts: its source and target as written. */
export function edgeKey(e) { return `${e.node?.attrs.source}>${e.node?.attrs.target || e.node?.attrs.name}`; }

/** elkjs's layout of a graph ({pos, routes}); ``run`` lays out an elkjs graph. Parts not
 *  connected to each other are packed to about the view's ``aspect`` (width / height) as
 *  elkjs does it (a big group is packed again by packParts). */
async function elkLayout(graph, run, aspect = 1.6) {
    const pid = (b, side, port) => `${b.key}|${side}|${port}`;
    const children = graph.boxes.map((b) => {
        const ports = [
            ...b.inputs.map((p) => ({ id: pid(b, "in", p), ...portOffset(b, "in", p), width: 0, height: 0, layoutOptions: { "org.eclipse.elk.port.side": "WEST" } })),
            ...b.outputs.map((p) => ({ id: pid(b, "out", p), ...portOffset(b, "out", p), width: 0, height: 0, layoutOptions: { "org.eclipse.elk.port.side": "EAST" } })),
        ];
        const opts = { "org.eclipse.elk.portConstraints": "FIXED_POS" };
        if (b.kind === "input" || b.kind === "external-in") opts["org.eclipse.elk.layered.layering.layerConstraint"] = "FIRST_SEPARATE";
        if (b.kind === "output" || b.kind === "external-out") opts["org.eclipse.elk.layered.layering.layerConstraint"] = "LAST_SEPARATE";
        return { id: b.key, width: b.w, height: b.h, ports, layoutOptions: opts };
    });
    const edges = graph.edges.map((e, i) => [e, i]).filter(([e]) => e.from.box && e.to.box).map(([e, i]) => ({
        id: "e" + i, sources: [pid(e.from.box, "out", e.from.port)], targets: [pid(e.to.box, "in", e.to.port)],
    }));
    const result = await run({
        id: "root",
        layoutOptions: {
            "org.eclipse.elk.algorithm": "layered",
            "org.eclipse.elk.direction": "RIGHT",
            "org.eclipse.elk.spacing.nodeNode": "40",
            "org.eclipse.elk.layered.spacing.nodeNodeBetweenLayers": "90",
            "org.eclipse.elk.spacing.componentComponent": "60",
            "org.eclipse.elk.layered.crossingMinimization.strategy": "LAYER_SWEEP",
            "org.eclipse.elk.padding": "[top=40,left=40,bottom=40,right=40]",
            "org.eclipse.elk.edgeRouting": "ORTHOGONAL",
            "org.eclipse.elk.layered.spacing.edgeNodeBetweenLayers": "20",
            "org.eclipse.elk.aspectRatio": String(Math.max(0.2, Math.min(5, aspect))),
        },
        children, edges,
    });
    const pos = new Map(result.children.map((c) => [c.id, { x: Math.round(c.x), y: Math.round(c.y) }]));
    // the connections as elkjs routed them around the boxes: points relative to the rounded
    // box positions, keyed by edgeKey
    const routes = new Map();
    const shift = new Map(result.children.map((c) => [c.id, [Math.round(c.x) - c.x, Math.round(c.y) - c.y]]));
    for (const re of result.edges || []) {
        const sec = re.sections?.[0];
        const e = graph.edges[+re.id.slice(1)];
        if (!sec || !e) continue;
        const [sx, sy] = shift.get(e.from.box.key), [tx, ty] = shift.get(e.to.box.key);
        const pts = [[sec.startPoint.x + sx, sec.startPoint.y + sy], ...(sec.bendPoints || []).map((b) => [b.x, b.y]),
            [sec.endPoint.x + tx, sec.endPoint.y + ty]];
        routes.set(edgeKey(e), pts);
    }
    return { pos, routes };
}

/** The parts of a graph not connected to each other (pins with the part they feed), each
 *  a list of boxes. */
function parts(graph) {
    const part = new Map(graph.boxes.map((b) => [b.key, b.key]));
    const find = (k) => { while (part.get(k) !== k) { part.set(k, part.get(part.get(k))); k = part.get(k); } return k; };
    for (const e of graph.edges) {
        if (e.from.box && e.to.box) part.set(find(e.from.box.key), find(e.to.box.key));
    }
    const out = new Map();
    for (const b of graph.boxes) {
        const k = find(b.key);
        if (!out.has(k)) out.set(k, []);
        out.get(k).push(b);
    }
    return [...out.values()];
}

/** The extent of some boxes at ``pos``: {list, x0, y0, w, h}. */
function extentOf(list, pos) {
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (const b of list) {
        const p = pos.get(b.key);
        x0 = Math.min(x0, p.x); y0 = Math.min(y0, p.y); x1 = Math.max(x1, p.x + b.w); y1 = Math.max(y1, p.y + b.h);
    }
    return { list, x0, y0, w: x1 - x0, h: y1 - y0 };
}

/**
 * A big group's layout made to fit a view of about ``aspect`` (width / height): its parts not
 * connected to each other packed in rows, in the order of their first box, and a part wider
 * than a row cut into strips along the data flow, one under the other (as a long line of
 * text is wrapped), from its positions in ``columns`` (a plain layered layout). elkjs packs the parts in a square of its own liking and lays a long chain
 * out in one row, which in a wide view leaves most of a big group out of sight. Returns
 * {pos, routes}: the routes of the parts moved whole are moved along; a part cut into strips
 * loses them (the editor routes those connections around the boxes).
 */
export function packParts(graph, pos, routes, aspect, columns = pos) {
    const boxArea = graph.boxes.reduce((sum, b) => sum + (b.w + GAP_X) * (b.h + GAP_Y), 0);
    const widestBox = Math.max(...graph.boxes.map((b) => b.w + GAP_X));
    const rowWidth = Math.max(widestBox, 1.2 * Math.sqrt(boxArea * Math.max(0.2, aspect)));
    const pieces = [];                   // [block, cut] in order
    const at = new Map(pos);
    for (const list of parts(graph)) {
        const g = extentOf(list, pos);
        if (g.w <= rowWidth) { pieces.push([g, false]); continue; }
        // cut along the data flow: the plain layered columns of ``columns`` (elkjs spreads
        // a long part over many lanes), a strip of them at a time
        const whole = extentOf(list, columns), strips = new Map();
        for (const b of list) {
            at.set(b.key, columns.get(b.key));
            const s = Math.floor((columns.get(b.key).x - whole.x0) / rowWidth);
            if (!strips.has(s)) strips.set(s, []);
            strips.get(s).push(b);
        }
        for (const s of [...strips.keys()].sort((a, b) => a - b)) pieces.push([extentOf(strips.get(s), columns), true]);
    }
    const moved = new Map(), shiftOf = new Map(), cut = new Set();
    let x = 40, y = 40, rowHeight = 0;
    for (const [g, wrapped] of pieces) {
        if (x > 40 && x + g.w > 40 + rowWidth) { x = 40; y += rowHeight + GAP_Y; rowHeight = 0; }
        const dx = x - g.x0, dy = y - g.y0;
        for (const b of g.list) {
            const p = at.get(b.key);
            moved.set(b.key, { x: p.x + dx, y: p.y + dy });
            shiftOf.set(b.key, [dx, dy]);
            if (wrapped) cut.add(b.key);
        }
        x += g.w + GAP_X;
        rowHeight = Math.max(rowHeight, g.h);
    }
    const newRoutes = new Map();
    for (const e of graph.edges) {
        const route = routes?.get(edgeKey(e));
        if (!route || !e.from.box || cut.has(e.from.box.key)) continue;
        const [dx, dy] = shiftOf.get(e.from.box.key);
        newRoutes.set(edgeKey(e), route.map(([px, py]) => [px + dx, py + dy]));
    }
    return { pos: moved, routes: newRoutes };
}

/** Longest-path layers along the connections, boxes stacked in each layer; a layer taller
 *  than a drawing of about ``aspect`` (width / height) allows is wrapped into more columns, so
 *  that a big flat group is a grid that fits the view. */
export function simpleLayout(graph, aspect = 1.6) {
    const layer = new Map(graph.boxes.map((b) => [b.key, 0]));
    for (let round = 0; round < graph.boxes.length; round++) {
        let changed = false;
        for (const e of graph.edges) {
            if (!e.from.box || !e.to.box || e.from.box === e.to.box) continue;
            const l = layer.get(e.from.box.key) + 1;
            if (l > layer.get(e.to.box.key) && l < graph.boxes.length) { layer.set(e.to.box.key, l); changed = true; }
        }
        if (!changed) break;
    }
    const cols = new Map();
    for (const b of graph.boxes) {
        const l = layer.get(b.key);
        if (!cols.has(l)) cols.set(l, []);
        cols.get(l).push(b);
    }
    const area = graph.boxes.reduce((sum, b) => sum + (b.w + GAP_X) * (b.h + GAP_Y), 0);
    const tallest = Math.max(0, ...graph.boxes.map((b) => b.h + GAP_Y));
    const height = Math.max(tallest, Math.sqrt(area / Math.max(0.2, aspect)));
    const pos = new Map();
    let x = 40;
    for (const l of [...cols.keys()].sort((a, b) => a - b)) {
        let y = 40, width = 0;
        for (const b of cols.get(l)) {
            if (y > 40 && y + b.h > 40 + height) { x += width + GAP_X; y = 40; width = 0; }
            pos.set(b.key, { x, y });
            y += b.h + GAP_Y;
            width = Math.max(width, b.w);
        }
        x += width + LAYER_GAP;
    }
    return pos;
}

const GAP_X = 40, GAP_Y = 40, LAYER_GAP = 90;
