// A group as a graph of boxes and edges, box geometry, and the automatic layout (elkjs,
// layered, left to right along the data flow) for groups whose file gives no _x, _y.
import { kids, elements, splitAddress } from "./model.js";

export const ELK_LIMIT = 300;   // boxes; a bigger group is drawn first with simpleLayout
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
export async function layout(graph, { force = false } = {}) {
    const comps = graph.boxes.filter(isComponent);
    const stored = new Map(comps.map((b) => [b.key, storedPosition(b)]));
    const manual = !force && comps.length > 0 && comps.every((b) => stored.get(b.key));
    let pos, routes = null, later = null;
    if (manual) {
        pos = new Map(comps.map((b) => [b.key, stored.get(b.key)]));
        placePins(graph, pos);
    } else if (graph.boxes.length > ELK_LIMIT) {
        const sign = signature(graph), kept = bigLayouts.get(sign);
        if (kept) { pos = new Map(kept.pos); routes = kept.routes; }
        else {
            pos = simpleLayout(graph);
            later = elkLayout(graph, layoutInWorker).then((r) => {
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
            ({ pos, routes } = await elkLayout(graph, async (g) => new (await loadElk())().layout(g)));
        } catch (e) {
            console.warn("elk layout failed, using the simple one:", e);
            pos = simpleLayout(graph);
        }
    }
    return { positions: pos, automatic: !manual, routes, later };
}

const bigLayouts = new Map();   // signature -> elkjs's {pos, routes}, the oldest first

/** What a layout depends on: the boxes with their sizes and ports, and the connections. */
function signature(graph) {
    return JSON.stringify([graph.boxes.map((b) => [b.key, b.w, b.h, b.inputs, b.outputs]), graph.edges.map(edgeKey)]);
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

/** elkjs's layout of a graph ({pos, routes}); ``run`` lays out an elkjs graph. */
async function elkLayout(graph, run) {
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

/** Longest-path layers along the connections, boxes stacked in each layer. */
export function simpleLayout(graph) {
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
    const pos = new Map();
    for (const [l, list] of cols) {
        let y = 40;
        for (const b of list) { pos.set(b.key, { x: 40 + l * (BOX_W + 90), y }); y += b.h + 40; }
    }
    return pos;
}
