// Orthogonal connection routes around boxes placed by hand. elkjs routes only the graphs it
// lays out itself (it has no router for fixed positions), so a connection whose box was
// moved is routed here: it leaves its output port to the right and enters its input port
// from the left, and in between runs along horizontal and vertical lines that keep a
// clearance from every box: the shortest such path with the fewest bends (A* over the lines
// through the boxes' sides and the middles between them, with a cost per bend), its inner
// segments then centred in their channels, beside (not on) other connections' segments.
// Boxes and segments are looked up in grid buckets (RectIndex), so that a route in a group of
// thousands of boxes costs what one among its neighbours costs.

const CLEARANCE = 10;      // drawing units kept free around boxes
const STUB = 20;           // straight run out of a port and into one
const BEND = 40;           // the cost of a bend, in drawing units of length
const PADS = [150, 600, Infinity];   // search areas around the ends, tried in turn
const MAX_NODES = 120000;  // a bigger search grid is not searched (the route is a plain one)
const SEPARATION = 8;      // between parallel segments of different connections in a channel
const LANE_GAP = 40;       // collinear segments of two connections at most this far apart share no line
const PLACES = 12;         // places tried on either side of a channel's middle

const strictlyInside = (p, o) => p[0] > o[0] && p[0] < o[2] && p[1] > o[1] && p[1] < o[3];

/** Whether the segment p-q passes through the interior of rectangle r (shrunk by ``inset``). */
export function crosses(p, q, r, inset = 1) {
    return Math.min(p[0], q[0]) < r[2] - inset && Math.max(p[0], q[0]) > r[0] + inset &&
        Math.min(p[1], q[1]) < r[3] - inset && Math.max(p[1], q[1]) > r[1] + inset;
}

const CELL = 256;          // the grid bucket of RectIndex, in drawing units

/** The bounding box of segment p-q widened by ``m``. */
export const segmentBox = (p, q, m = 0) =>
    [Math.min(p[0], q[0]) - m, Math.min(p[1], q[1]) - m, Math.max(p[0], q[0]) + m, Math.max(p[1], q[1]) + m];

/** Items with bounding boxes ([x0, y0, x1, y1]) in grid buckets: those near an area are
 *  found without looking at all of them. */
export class RectIndex {
    /** ``items``: rectangles (their own boxes), or [item, box] pairs with ``boxOf`` null. */
    constructor(items = [], boxOf = (r) => r) {
        this.cells = new Map();
        this.boxes = new Map();
        this.bounds = null;
        for (const it of items) this.add(it, boxOf(it));
    }

    get size() { return this.boxes.size; }

    add(item, box = item) {
        this.boxes.set(item, box);
        const b = this.bounds;
        this.bounds = b ? [Math.min(b[0], box[0]), Math.min(b[1], box[1]), Math.max(b[2], box[2]), Math.max(b[3], box[3])] : [...box];
        for (let i = Math.floor(box[0] / CELL); i <= Math.floor(box[2] / CELL); i++) {
            for (let j = Math.floor(box[1] / CELL); j <= Math.floor(box[3] / CELL); j++) {
                const k = i * 65536 + j;
                const list = this.cells.get(k);
                if (list) list.push(item); else this.cells.set(k, [item]);
            }
        }
    }

    /** The items whose boxes touch ``area`` (sides included). */
    near(area) {
        if (!this.bounds) return [];
        const a = [Math.max(area[0], this.bounds[0]), Math.max(area[1], this.bounds[1]), Math.min(area[2], this.bounds[2]), Math.min(area[3], this.bounds[3])];
        if (a[0] > a[2] || a[1] > a[3]) return [];
        const out = [], seen = new Set();
        for (let i = Math.floor(a[0] / CELL); i <= Math.floor(a[2] / CELL); i++) {
            for (let j = Math.floor(a[1] / CELL); j <= Math.floor(a[3] / CELL); j++) {
                for (const it of this.cells.get(i * 65536 + j) || []) {
                    if (seen.has(it)) continue;
                    seen.add(it);
                    const b = this.boxes.get(it);
                    if (b[0] <= area[2] && b[2] >= area[0] && b[1] <= area[3] && b[3] >= area[1]) out.push(it);
                }
            }
        }
        return out;
    }
}

/** A RectIndex of segments ([p, q]). */
export const segmentIndex = (segments = []) => new RectIndex(segments, (s) => segmentBox(s[0], s[1]));

/**
 * The route of a connection from output port ``a`` to input port ``b`` ({x, y}) around the
 * boxes ``rects`` ([x0, y0, x1, y1], the connection's own boxes among them; a list or a
 * RectIndex): a list of [x, y] points with axis-parallel segments. ``others``: the segments
 * ([p, q]) of other connections (a list or a segmentIndex), which its middle segments keep
 * SEPARATION from where there is room.
 */
export function orthogonalRoute(a, b, rects, others = []) {
    const boxes = rects instanceof RectIndex ? rects : new RectIndex(rects);
    const segments = others instanceof RectIndex ? others : segmentIndex(others);
    const s = [a.x + STUB, a.y], t = [b.x - STUB, b.y];
    for (const clearance of [CLEARANCE, 2]) {
        for (const pad of PADS) {
            const path = search(s, t, boxes, clearance, pad);
            if (path === undefined) break;               // too big to search
            if (path) return simplify(centred([[a.x, a.y], ...path, [b.x, b.y]], boxes, clearance, segments));
        }
    }
    const mx = s[0] <= t[0] ? (s[0] + t[0]) / 2 : s[0];
    return simplify([[a.x, a.y], s, [mx, s[1]], [mx, t[1]], t, [b.x, b.y]]);
}

/** Points without repeats and without the middle one of three on a line. */
function simplify(pts) {
    const out = [];
    for (const p of pts) {
        if (out.length && out.at(-1)[0] === p[0] && out.at(-1)[1] === p[1]) continue;
        if (out.length >= 2) {
            const [u, v] = [out.at(-2), out.at(-1)];
            if ((u[0] === v[0] && v[0] === p[0]) || (u[1] === v[1] && v[1] === p[1])) out.pop();
        }
        out.push(p);
    }
    return out;
}

function lowerBound(list, v) {
    let lo = 0, hi = list.length;
    while (lo < hi) { const m = (lo + hi) >> 1; if (list[m] < v) lo = m + 1; else hi = m; }
    return lo;
}

/** The sorted coordinates of the search grid: the given ones and the middles between them. */
function gridLines(values) {
    const v = [...new Set(values)].sort((p, q) => p - q);
    const out = [];
    v.forEach((x, i) => { out.push(x); if (i + 1 < v.length) out.push((x + v[i + 1]) / 2); });
    return out;
}

/** The grid path from s to t (a list of points), null when there is none, undefined when
 *  the grid would be too big. */
function search(s, t, rects, c, pad) {
    let area;
    if (pad === Infinity) {
        const r = rects.bounds || [s[0], s[1], s[0], s[1]];
        area = [Math.min(s[0], t[0], r[0]), Math.min(s[1], t[1], r[1]), Math.max(s[0], t[0], r[2]), Math.max(s[1], t[1], r[3])];
        area = [area[0] - 4 * c - STUB, area[1] - 4 * c - STUB, area[2] + 4 * c + STUB, area[3] + 4 * c + STUB];
    } else {
        area = [Math.min(s[0], t[0]) - pad, Math.min(s[1], t[1]) - pad, Math.max(s[0], t[0]) + pad, Math.max(s[1], t[1]) + pad];
    }
    const clampX = (x) => Math.max(area[0], Math.min(area[2], x)), clampY = (y) => Math.max(area[1], Math.min(area[3], y));
    const obs = [];
    for (const r of rects.near([area[0] - c, area[1] - c, area[2] + c, area[3] + c])) {
        const o = [r[0] - c, r[1] - c, r[2] + c, r[3] + c];
        if (o[0] >= area[2] || o[2] <= area[0] || o[1] >= area[3] || o[3] <= area[1]) continue;
        if (strictlyInside(s, o) || strictlyInside(t, o)) return null;
        obs.push([clampX(o[0]), clampY(o[1]), clampX(o[2]), clampY(o[3])]);
    }
    const xs = gridLines([s[0], t[0], area[0], area[2], ...obs.flatMap((o) => [o[0], o[2]])]);
    const ys = gridLines([s[1], t[1], area[1], area[3], ...obs.flatMap((o) => [o[1], o[3]])]);
    const nx = xs.length, ny = ys.length, n = nx * ny;
    if (n > MAX_NODES) return undefined;
    // blocked: a node strictly inside a box, a grid segment through a box's interior
    const blockedNode = new Uint8Array(n), blockedH = new Uint8Array(n), blockedV = new Uint8Array(n);
    for (const o of obs) {
        const i0 = lowerBound(xs, o[0]), i1 = lowerBound(xs, o[2]), j0 = lowerBound(ys, o[1]), j1 = lowerBound(ys, o[3]);
        for (let i = i0; i <= i1; i++) {
            for (let j = j0; j <= j1; j++) {
                const inX = i > i0 && i < i1, inY = j > j0 && j < j1, k = i * ny + j;
                if (inX && inY) blockedNode[k] = 1;
                if (inY && i < i1) blockedH[k] = 1;
                if (inX && j < j1) blockedV[k] = 1;
            }
        }
    }
    const start = lowerBound(xs, s[0]) * ny + lowerBound(ys, s[1]);
    const goal = lowerBound(xs, t[0]) * ny + lowerBound(ys, t[1]);
    const tx = t[0], ty = t[1];
    // A* over (node, direction): 0 east, 1 west, 2 south, 3 north; no turning back
    const cost = new Float64Array(n * 4).fill(Infinity);
    const prev = new Int32Array(n * 4).fill(-1);
    const heap = new Heap();
    const h = (k) => Math.abs(xs[(k / ny) | 0] - tx) + Math.abs(ys[k % ny] - ty);
    cost[start * 4] = 0;
    heap.push(h(start), start * 4);
    while (heap.size) {
        const [f, state] = heap.pop();
        const k = state >> 2, d = state & 3, g = cost[state];
        if (f > g + h(k) + 1e-9) continue;              // a stale entry
        if (k === goal && d !== 1) {
            const path = [];
            for (let st = state; st >= 0; st = prev[st]) path.push([xs[(st >> 2) / ny | 0], ys[(st >> 2) % ny]]);
            return path.reverse();
        }
        const i = (k / ny) | 0, j = k % ny;
        for (let nd = 0; nd < 4; nd++) {
            if (nd === (d ^ 1)) continue;
            let m, len;
            if (nd === 0) { if (i + 1 >= nx || blockedH[k]) continue; m = k + ny; len = xs[i + 1] - xs[i]; }
            else if (nd === 1) { if (i === 0 || blockedH[k - ny]) continue; m = k - ny; len = xs[i] - xs[i - 1]; }
            else if (nd === 2) { if (j + 1 >= ny || blockedV[k]) continue; m = k + 1; len = ys[j + 1] - ys[j]; }
            else { if (j === 0 || blockedV[k - 1]) continue; m = k - 1; len = ys[j] - ys[j - 1]; }
            if (blockedNode[m]) continue;
            const ng = g + len + (nd === d ? 0 : BEND) + (m === goal && nd !== 0 ? BEND : 0);
            const ns = m * 4 + nd;
            if (ng < cost[ns]) { cost[ns] = ng; prev[ns] = state; heap.push(ng + h(m), ns); }
        }
    }
    return null;
}

/** Whether segment p-q runs along one of ``others``: parallel, closer than SEPARATION, with
 *  spans that overlap or come within LANE_GAP of each other (two connections on one line
 *  with a short gap between them read as one: which input each reaches cannot be seen). */
function alongside(p, q, others) {
    const axis = p[0] === q[0] ? 0 : 1, other = 1 - axis;
    const lo = Math.min(p[other], q[other]), hi = Math.max(p[other], q[other]);
    return others.near(segmentBox(p, q, LANE_GAP)).some(([u, v]) => u[axis] === v[axis] && Math.abs(u[axis] - p[axis]) < SEPARATION &&
        Math.min(u[other], v[other]) < hi + LANE_GAP && Math.max(u[other], v[other]) > lo - LANE_GAP);
}

/** The path with each inner segment between two bends that turn the same way (a Z) moved
 *  to the middle of its free channel, or the nearest place to it beside other connections'
 *  segments, where that leaves every segment clear of the boxes. */
function centred(path, rects, c, others) {
    const pts = simplify(path.map((p) => [...p]));
    // a segment from a port keeps clear of the boxes' insides only (it starts at a side)
    const clear = (p, q) => p === pts[0] || q === pts.at(-1) ? !rects.near(segmentBox(p, q)).some((r) => crosses(p, q, r))
        : !rects.near(segmentBox(p, q, c)).some((r) => crosses(p, q, [r[0] - c, r[1] - c, r[2] + c, r[3] + c], 0));
    for (let k = 1; k + 2 < pts.length; k++) {
        const p = pts[k], q = pts[k + 1], before = pts[k - 1], after = pts[k + 2];
        const axis = p[0] === q[0] ? 0 : 1;               // 0: a vertical segment, moved along x
        const other = 1 - axis;
        const lo = Math.min(before[axis], after[axis]), hi = Math.max(before[axis], after[axis]);
        if (!(p[axis] >= lo && p[axis] <= hi)) continue;  // a U turn: it stays
        // the nearest boxes on either side of the segment, over its span
        const span = [Math.min(p[other], q[other]), Math.max(p[other], q[other])];
        let left = lo, right = hi;
        const around = axis === 0 ? [lo, span[0], hi, span[1]] : [span[0], lo, span[1], hi];
        for (const r of rects.near(around)) {
            if (r[other] >= span[1] || r[other + 2] <= span[0]) continue;
            if (r[axis + 2] <= p[axis]) left = Math.max(left, r[axis + 2]);
            if (r[axis] >= p[axis]) right = Math.min(right, r[axis]);
        }
        const mid = (left + right) / 2;
        let fallback = null;
        for (let step = 0; Math.abs(step) <= PLACES && Math.abs(step) * SEPARATION <= (right - left) / 2; step = step > 0 ? -step : 1 - step) {
            const np = [...p], nq = [...q];
            np[axis] = nq[axis] = mid + step * SEPARATION;
            if (!(clear(before, np) && clear(np, nq) && clear(nq, after))) continue;
            if (!alongside(np, nq, others) && !alongside(before, np, others) && !alongside(nq, after, others)) {
                fallback = null; pts[k] = np; pts[k + 1] = nq; break;
            }
            if (!alongside(np, nq, others)) fallback ??= [np, nq];
        }
        if (fallback) [pts[k], pts[k + 1]] = fallback;
    }
    return pts;
}

/** A binary min-heap of (priority, value). */
class Heap {
    constructor() { this.keys = []; this.values = []; }
    get size() { return this.keys.length; }
    push(key, value) {
        const { keys, values } = this;
        let i = keys.length;
        keys.push(key); values.push(value);
        while (i > 0) {
            const p = (i - 1) >> 1;
            if (keys[p] <= key) break;
            keys[i] = keys[p]; values[i] = values[p]; i = p;
        }
        keys[i] = key; values[i] = value;
    }
    pop() {
        const { keys, values } = this;
        const top = [keys[0], values[0]];
        const key = keys.pop(), value = values.pop();
        if (keys.length) {
            let i = 0;
            for (;;) {
                const l = 2 * i + 1, r = l + 1;
                let m = i, mk = key;
                if (l < keys.length && keys[l] < mk) { m = l; mk = keys[l]; }
                if (r < keys.length && keys[r] < mk) { m = r; mk = keys[r]; }
                if (m === i) break;
                keys[i] = keys[m]; values[i] = values[m]; i = m;
            }
            keys[i] = key; values[i] = value;
        }
        return top;
    }
}
