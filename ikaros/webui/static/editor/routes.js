// The routes of one group's connections as drawn: elkjs's (from an automatic layout) while
// their ends stay where elkjs put them and nothing was moved across them; any other
// connection is routed around the boxes by router.js, again when one of its boxes moves or
// a box is moved onto or away from its route. Groups of more than ELK_LIMIT boxes are drawn
// with curves.
import { ELK_LIMIT, edgeKey, portOffset } from "./layout.js";
import { crosses, orthogonalRoute } from "./router.js";

const NEAR = 30;    // a route this close to a box that moved is routed again

const rectOf = (b, p) => [p.x, p.y, p.x + b.w, p.y + b.h];
const sameRect = (a, b) => a && b && a[0] === b[0] && a[1] === b[1] && a[2] === b[2] && a[3] === b[3];
const near = (pts, r) => pts.some((p, i) => i > 0 && crosses(pts[i - 1], p, [r[0] - NEAR, r[1] - NEAR, r[2] + NEAR, r[3] + NEAR], 0));

export class RouteKeeper {
    constructor(group) {
        this.group = group;
        this.routes = new Map();     // edgeKey -> {a, b (port points), pts}
        this.rects = new Map();      // box key -> [x0, y0, x1, y1] when last routed
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

    /** The route of every connection of ``graph`` at ``positions``: Map edgeKey -> points. */
    routesFor(graph, positions) {
        const out = new Map();
        if (graph.boxes.length > ELK_LIMIT) return out;
        const rects = new Map(graph.boxes.filter((b) => positions.has(b.key)).map((b) => [b.key, rectOf(b, positions.get(b.key))]));
        const changed = [];                 // where boxes were and are, of those that moved
        for (const [k, r] of rects) if (!sameRect(r, this.rects.get(k))) { changed.push(r); if (this.rects.has(k)) changed.push(this.rects.get(k)); }
        for (const [k, r] of this.rects) if (!rects.has(k)) changed.push(r);
        this.rects = rects;
        const all = [...rects.values()];
        const todo = [];
        for (const e of graph.edges) {
            if (!e.from.box || !e.to.box) continue;
            const ends = RouteKeeper.ends(e, positions);
            if (!ends) continue;
            const [a, b] = ends, key = edgeKey(e);
            const r = this.routes.get(key);
            const kept = r && r.a.x === a.x && r.a.y === a.y && r.b.x === b.x && r.b.y === b.y &&
                !changed.some((c) => near(r.pts, c)) && !r.pts.some((p, i) => i > 0 && all.some((q) => crosses(r.pts[i - 1], p, q)));
            if (kept) out.set(key, r.pts); else todo.push([key, a, b]);
        }
        // the new routes keep beside the others' segments
        const segments = [...out.values()].flatMap((pts) => pts.slice(1).map((p, i) => [pts[i], p]));
        for (const [key, a, b] of todo) {
            const pts = orthogonalRoute(a, b, all, segments);
            this.routes.set(key, { a, b, pts });
            out.set(key, pts);
            segments.push(...pts.slice(1).map((p, i) => [pts[i], p]));
        }
        return out;
    }
}
