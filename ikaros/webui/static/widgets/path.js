// path: poly-lines from coordinate rows.
// Attributes: source; order (col: each row is one line of x,y pairs from column select on,
// and when every row holds one pair, as an n x 2 matrix, the rows are the points of one line;
// row: one line through the rows, each row a point with x, y in columns select, select+1); select|select_x, count|point_count,
// color|stroke_color and fill|fill_color (cycle per line), lineWidth|line_width,
// lineCap|line_cap, lineJoin|line_join, close (closes and fills), arrow (an arrow head at the
// last point); coordinates: min_x|x_min .. max_y|y_max, flips.
import { CanvasWidget, asRows } from "./widget.js";
import { pointsFrom } from "./marker.js";

export default class Path extends CanvasWidget {
    subscriptions() { const p = this.path("source"); return p ? [{ path: p, format: "raw" }] : []; }

    update(frame) {
        const item = frame.get(this.path("source"));
        if (!item) return;
        const pts = pointsFrom(this, item);
        if (this.str(["order"], "col") === "row") {
            const sel = this.int(["select", "select_x"], 0);
            // one point per row: the pair at column select
            this.lines = [asRows(item).filter((r) => r.length >= sel + 2).map((r) => ({ x: r[sel], y: r[sel + 1] }))];
        } else if (pts.length && pts.every((p) => p.series === p.row)) {
            // one x,y pair per row (an n x 2 matrix such as a chain of joints): the rows
            // are the points of one line
            this.lines = [pts];
        } else {
            const lines = new Map();
            for (const p of pts) {
                if (!lines.has(p.row)) lines.set(p.row, []);
                lines.get(p.row).push(p);
            }
            this.lines = [...lines.values()];
        }
        this.draw();
    }

    draw() {
        if (!this.lines || !this.fit()) return;
        const g = this.g, map = this.coordinates();
        const strokes = this.colors(["color", "stroke_color"]);
        const fills = this.list(["fill", "fill_color"], []);
        const close = this.bool(["close"], false), arrow = this.bool(["arrow"], false);
        this.lineStyle(g);
        this.lines.forEach((line, i) => {
            if (line.length < 1) return;
            g.strokeStyle = strokes[i % strokes.length];
            g.beginPath();
            line.forEach((p, k) => { const x = map.x(p.x), y = map.y(p.y); if (k === 0) g.moveTo(x, y); else g.lineTo(x, y); });
            if (close) {
                g.closePath();
                if (fills.length) { g.fillStyle = fills[i % fills.length]; g.fill(); }
            }
            g.stroke();
            if (arrow && line.length >= 2) {
                const a = line[line.length - 2], b = line[line.length - 1];
                const x1 = map.x(a.x), y1 = map.y(a.y), x2 = map.x(b.x), y2 = map.y(b.y);
                const ang = Math.atan2(y2 - y1, x2 - x1), L = 6 + 2 * g.lineWidth;
                g.fillStyle = strokes[i % strokes.length];
                g.beginPath();
                g.moveTo(x2, y2);
                g.lineTo(x2 - L * Math.cos(ang - 0.4), y2 - L * Math.sin(ang - 0.4));
                g.lineTo(x2 - L * Math.cos(ang + 0.4), y2 - L * Math.sin(ang + 0.4));
                g.closePath();
                g.fill();
            }
        });
    }
}
