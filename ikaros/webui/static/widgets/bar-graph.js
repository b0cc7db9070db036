// bar-graph: one bar per element, one group of bars per row.
// Attributes: source, direction|orientation (vertical/horizontal), transpose, labels,
// color|stroke_color, fill|fill_color (comma lists cycle per bar), lineWidth|line_width,
// min|y_min, max|y_max, auto|auto_range, include_zero, decimals, show_values.
import { CanvasWidget, asRows, formatNumber } from "./widget.js";
import { dataRange } from "./axes.js";

export default class BarGraph extends CanvasWidget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        this.rows = null;
        this.canvas.addEventListener("click", () => {
            if (this.rows) this.canvas.title = this.rows.map((r) => Array.from(r).map((v) => formatNumber(v, 3)).join(", ")).join("\n");
        });
    }

    subscriptions() { const p = this.path("source"); return p ? [{ path: p, format: "raw" }] : []; }

    update(frame) {
        const item = frame.get(this.path("source"));
        if (!item) return;
        let rows = asRows(item).map((r) => Array.from(r));
        if (this.bool(["transpose"], false) && rows.length) rows = rows[0].map((_, c) => rows.map((r) => r[c]));
        this.rows = rows;
        this.draw();
    }

    draw() {
        if (!this.rows || !this.fit()) return;
        const g = this.g, w = this.width, h = this.height;
        const horizontal = this.str(["direction", "orientation"], "vertical") === "horizontal";
        const all = this.rows.flat();
        // without min and max the range follows the data (with 0), as Ikaros 3's auto_range
        const given = this.raw(["min", "y_min", "value_min"]) !== undefined || this.raw(["max", "y_max", "value_max"]) !== undefined;
        const [min, max] = given ? this.range(all, 0, 1) : dataRange(all, undefined, undefined, this.bool(["include_zero"], true));
        this.valueRange = [min, max];
        const fills = this.colors(["fill", "fill_color"]);
        const strokes = this.list(["color", "stroke_color"], []);
        const labels = this.list(["labels"], []);
        const decimals = this.int(["decimals"], -1);
        const showValues = this.bool(["show_values"], false);
        const labelSpace = labels.length ? 14 : 0;
        const n = all.length || 1;
        const groups = this.rows.length;
        const slots = n + (groups - 1) * 0.5;
        const span = (horizontal ? h : w - 0) ;
        const slot = span / slots;
        const scale = (v) => (Math.min(Math.max(v, min), max) - min) / (max - min || 1);
        const zero = scale(Math.min(Math.max(0, min), max));
        this.lineStyle(g);
        let k = 0, pos = 0;
        g.font = "10px sans-serif";
        g.textAlign = "center";
        for (let r = 0; r < groups; r++) {
            for (let c = 0; c < this.rows[r].length; c++, k++) {
                const v = this.rows[r][c];
                const a = scale(v);
                g.fillStyle = fills[k % fills.length];
                const x0 = pos * slot + slot * 0.1, bw = slot * 0.8;
                if (horizontal) {
                    const left = Math.min(a, zero) * w, right = Math.max(a, zero) * w;
                    g.fillRect(left, x0, right - left, bw);
                    if (strokes.length) { g.strokeStyle = strokes[k % strokes.length]; g.strokeRect(left, x0, right - left, bw); }
                } else {
                    const hh = h - labelSpace;
                    const top = hh - Math.max(a, zero) * hh, bottom = hh - Math.min(a, zero) * hh;
                    g.fillRect(x0, top, bw, bottom - top);
                    if (strokes.length) { g.strokeStyle = strokes[k % strokes.length]; g.strokeRect(x0, top, bw, bottom - top); }
                    g.fillStyle = this.cssVar("--text-color", "#333");
                    if (labels.length) g.fillText(labels[k % labels.length], x0 + bw / 2, h - 3);
                    if (showValues) g.fillText(formatNumber(v, decimals < 0 ? 2 : decimals), x0 + bw / 2, Math.max(10, top - 2));
                }
                pos += 1;
            }
            pos += 0.5;
        }
        // the zero line (the bars' base), drawn even when every bar is 0
        g.strokeStyle = this.cssVar("--muted-color", "#888");
        g.lineWidth = 1;
        g.beginPath();
        if (horizontal) { g.moveTo(zero * w, 0); g.lineTo(zero * w, h); }
        else { const y = (h - labelSpace) * (1 - zero); g.moveTo(0, y); g.lineTo(w, y); }
        g.stroke();
    }
}
