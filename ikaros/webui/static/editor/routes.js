// The routes of one group's connections as drawn: elkjs's (from an automatic layout) while
// their ends stay where elkjs put them and nothing was moved across them; any other
// connection is routed around the boxes by router.js, again when one of its boxes moves or
// a box is moved onto or away from its route. In a big group only the connections near the
// view are routed at once; the others wait for routeSome (the editor calls it while the
// page idles) and are drawn as curves meanwhile.
import { edgeKey, portOffset } from "./layout.js";
import { RectIndex, crosses, orthogonalRoute, segmentBox, segmentIndex } from "./router.js";

const NEAR = 30;    // a route this close to a box that moved is routed again
const REACH = 700;  // how far around its ends a new route may run (router.js searches 600 first)

const rectOf = (b, p) => [p.x, p.y, p.x + b.w, p.y + b.h];
const sameRect = (a, b) => a && b && a[0] === b[0] && a[1] === b[1] && a[2] === b[2] && a[3] === b[3];
const segmentsOf = (pts) => pts.slice(1).map((p, i) => [pts[i], p]);
const boundsOf = (pts) => [[Math.min(...pts.map((p) => p[0])), Math.min(...pts.map((p) => p[1]))],
    [Math.max(...pts.map((p) => p[0])), Math.max(...pts.map((p) => p[1]))]];
const touches = (r, area) => r[0] <= area[2] && r[2] >= area[0] && r[1] <= area[3] && r[3] >= area[1];

export class RouteKeeper {
    constructor(group) {
        this.group = group;
        this.routes = new Map();     // edgeKey -> {a, b (port points), pts}
        this.rects = new Map();      // box key -> [x0, y0, x1, y1] when last routed
        this.current = new Map();    // the routes as last given out (routeSome adds to it)
        this.pending = [];           // [key, a, b] of the connections not yet routed
    }

    /** The port points of a connection at the given positions, or null. */
    static ends(e, positions) {
        const p = positions.get(e.from.box.key), q = positions.get(e.to.box.key);
        if (!p || !q) return null;
        const o = portOffset(e.from.box, "out", e.from.port), i = portOffset(e.to.box, "in", e.to.port);
        return [{ x: p.x + o.x, y: p.y + o.y }, { x: q.x + i.x, y: q.y + i.y }];
    }

    /** Keep elkjs's routes (Map edgeKey -> points) of a layout at ``positions``. */
    keepLayout(graph, routes, positions) {
        this.routes.clear();
        for (const e of graph.edges) {
            const pts = e.from.box && e.to.box && routes.get(edgeKey(e));
            const ends = pts && RouteKeeper.ends(e, positions);
            if (ends) this.routes.set(edgeKey(e), { a: ends[0], b: ends[1], pts });
        }
        this.rects = new Map(graph.boxes.filter((b) => positions.has(b.key)).map((b) => [b.key, rectOf(b, positions.get(b.key))]));
    }

    /**
     * The route of every connection of ``graph`` at ``positions``: Map edgeKey -> points.
     * With an ``area`` ([x0, y0, x1, y1]), a connection to be routed anew whose ends span a
     * rectangle apart from it is left out and waits in ``pending`` for routeSome.
     */
    routesFor(graph, positions, area = null) {
        const out = new Map();
        const rects = new Map(graph.boxes.filter((b) => positions.has(b.key)).map((b) => [b.key, rectOf(b, positions.get(b.key))]));
        const changed = new RectIndex();    // where boxes were and are, of those that moved, widened by NEAR
        const moved = (r) => changed.add([r[0] - NEAR, r[1] - NEAR, r[2] + NEAR, r[3] + NEAR]);
        for (const [k, r] of rects) if (!sameRect(r, this.rects.get(k))) { moved(r); if (this.rects.has(k)) moved(this.rects.get(k)); }
        for (const [k, r] of this.rects) if (!rects.has(k)) moved(r);
        this.rects = rects;
        const all = new RectIndex(rects.values());
        const through = (p, q, index, inset) => index.near(segmentBox(p, q)).some((r) => crosses(p, q, r, inset));
        const todo = [];
        for (const e of graph.edges) {
            if (!e.from.box || !e.to.box) continue;
            const ends = RouteKeeper.ends(e, positions);
            if (!ends) continue;
            const [a, b] = ends, key = edgeKey(e);
            const r = this.routes.get(key);
            // a route found clear of every box needs checking only against the boxes that moved
            const kept = r && r.a.x === a.x && r.a.y === a.y && r.b.x === b.x && r.b.y === b.y &&
                !segmentsOf(r.pts).some(([p, q]) => through(p, q, changed, 0) || (!r.clear && through(p, q, all, 1)));
            if (kept) { r.clear = true; out.set(key, r.pts); } else todo.push([key, a, b]);
        }
        this.current = out;
        this.pending = [];
        const now = [];
        for (const job of todo) {
            if (area && !touches(segmentBox([job[1].x, job[1].y], [job[2].x, job[2].y]), area)) {
                this.pending.push(job);
                this.routes.delete(job[0]);
            } else now.push(job);
        }
        // the new routes keep beside the others' segments: those within reach of the new
        // routes, all of them when some wait for later
        let reach = null;
        for (const [, a, b] of this.pending.length ? [] : now) {
            const r = segmentBox([a.x, a.y], [b.x, b.y], REACH);
            reach = reach ? [Math.min(reach[0], r[0]), Math.min(reach[1], r[1]), Math.max(reach[2], r[2]), Math.max(reach[3], r[3])] : r;
        }
        const segments = [];
        if (now.length || this.pending.length) {
            for (const pts of out.values()) if (!reach || touches(segmentBox(...boundsOf(pts)), reach)) segments.push(...segmentsOf(pts));
        }
        this.index = { all, segments: segmentIndex(segments) };
        for (const job of now) this.route(job);
        return out;
    }

    route([key, a, b]) {
        const pts = orthogonalRoute(a, b, this.index.all, this.index.segments);
        this.routes.set(key, { a, b, pts, clear: false });
        this.current.set(key, pts);
        for (const s of segmentsOf(pts)) this.index.segments.add(s, segmentBox(s[0], s[1]));
    }

    /**
     * Route pending connections, those touching ``area`` first, while ``more()`` is true:
     * {inArea: how many of those routed touch the area, leftInArea, left}.
     */
    routeSome(more, area = null) {
        const inside = (job) => area && touches(segmentBox([job[1].x, job[1].y], [job[2].x, job[2].y]), area);
        if (area) this.pending.sort((p, q) => inside(q) - inside(p));
        let inArea = 0;
        while (this.pending.length && more()) {
            const job = this.pending.shift();
            if (inside(job)) inArea++;
            this.route(job);
        }
        return { inArea, leftInArea: area ? this.pending.filter(inside).length : this.pending.length, left: this.pending.length };
    }
}
