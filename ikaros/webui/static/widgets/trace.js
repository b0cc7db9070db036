// trace: the recent path of a point, fading towards the past. The point is (x, y) from
// source (its first two values, or columns select_x, select_y of a row) or x_source and
// y_source. Every tick's position is drawn: the buffers are subscribed as "history".
// Attributes: source | x_source + y_source, select_x (0), select_y (1), history_length
// (ticks kept, 100), x_min, x_max, y_min, y_max (0..1 each), flip_y_canvas|flipYCanvas,
// color|stroke_color, line_width (2).
import { CanvasWidget } from "./widget.js";

export default class Trace extends CanvasWidget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        this.points = [];        // [tick, x, y]
    }

    subscriptions() {
        return ["source", "x_source", "y_source"].map((a) => this.path(a)).filter(Boolean).map((path) => ({ path, format: "history", points: 8192 }));
    }

    /** [ticks, value at i of element e] of a history item (the max of an envelope column). */
    static samples(item) {
        const n = (item.buffer_shape || [1]).reduce((a, b) => a * b, 1), k = item.mode === "envelope" ? 2 : 1;
        return { ticks: item.ticks, at: (i, e) => item.data[(i * k + (k - 1)) * n + e] };
    }

    update(frame) {
        const one = frame.get(this.path("source"), "history");
        const xs = frame.get(this.path("x_source"), "history"), ys = frame.get(this.path("y_source"), "history");
        const sx = this.int(["select_x"], 0), sy = this.int(["select_y"], 1);
        let add = [];
        if (one) {
            const s = Trace.samples(one);
            add = s.ticks.map((t, i) => [t, s.at(i, sx), s.at(i, sy)]);
        } else if (xs && ys) {
            const a = Trace.samples(xs), b = Trace.samples(ys);
            add = a.ticks.map((t, i) => [t, a.at(i, 0), b.at(i, 0)]);
        } else return;
        if (add.length && this.points.length && add[0][0] <= this.points.at(-1)[0]) this.points = this.points.filter((p) => p[0] < add[0][0]);
        this.points.push(...add);
        const keep = this.int(["history_length"], 100);
        if (this.points.length && this.points.at(-1)[0] - this.points[0][0] >= keep) {
            const from = this.points.at(-1)[0] - keep;
            this.points = this.points.filter((p) => p[0] > from);
        }
        this.draw();
    }

    draw() {
        if (!this.points.length || !this.fit()) return;
        const g = this.g, map = this.coordinates(), n = this.points.length;
        g.strokeStyle = g.fillStyle = this.colors(["color", "stroke_color"])[0];
        g.lineWidth = this.num(["line_width", "lineWidth"], 2);
        for (let i = 1; i < n; i++) {
            g.globalAlpha = 0.15 + 0.85 * (i / (n - 1));
            g.beginPath();
            g.moveTo(map.x(this.points[i - 1][1]), map.y(this.points[i - 1][2]));
            g.lineTo(map.x(this.points[i][1]), map.y(this.points[i][2]));
            g.stroke();
        }
        g.globalAlpha = 1;
        const [, x, y] = this.points.at(-1);
        g.beginPath(); g.arc(map.x(x), map.y(y), 4, 0, 2 * Math.PI); g.fill();
    }
}
