// plot: a time series of each (selected) element over the last buffer_size updates.
// Attributes: source, select (comma list of element indices; v3 select_x), buffer_size
// (0: the widget width), min|y_min, max|y_max, auto|auto_range, color|stroke_color (cycles
// per series), lineWidth|line_width, show_y_axis / decimals (scale labels).
import { CanvasWidget, formatNumber } from "./widget.js";

export default class Plot extends CanvasWidget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        this.series = [];          // one array per plotted element
        this.lastTick = null;
    }

    subscriptions() { const p = this.path("source"); return p ? [{ path: p, format: "raw" }] : []; }

    selection(n) {
        const sel = this.list(["select", "select_x"], []).filter((s) => s !== "").map((s) => parseInt(s, 10)).filter((i) => i >= 0 && i < n);
        return sel.length ? sel : Array.from({ length: n }, (_, i) => i);
    }

    update(frame) {
        const item = frame.get(this.path("source"));
        if (!item) return;
        if (frame.tick === this.lastTick) return;
        this.lastTick = frame.tick;
        const sel = this.selection(item.data.length);
        const size = this.int(["buffer_size"], 50) || Math.max(10, this.body.clientWidth);
        if (this.series.length !== sel.length) this.series = sel.map(() => []);
        sel.forEach((idx, i) => {
            const s = this.series[i];
            s.push(item.data[idx]);
            while (s.length > size) s.shift();
        });
        this.size = size;
        this.draw();
    }

    draw() {
        if (!this.fit()) return;
        const g = this.g, w = this.width, h = this.height;
        const all = this.series.flat();
        const [min, max] = this.range(all, 0, 1);
        const colors = this.colors(["color", "stroke_color"]);
        const y = (v) => h - ((v - min) / (max - min || 1)) * h;
        g.strokeStyle = this.cssVar("--grid-color", "#ccc");
        g.lineWidth = 0.5;
        g.beginPath();
        g.moveTo(0, y(Math.min(Math.max(0, min), max)));
        g.lineTo(w, y(Math.min(Math.max(0, min), max)));
        g.stroke();
        this.lineStyle(g);
        const n = this.size || 50;
        this.series.forEach((s, i) => {
            g.strokeStyle = colors[i % colors.length];
            g.beginPath();
            s.forEach((v, k) => {
                const px = (k / Math.max(1, n - 1)) * w;
                const py = y(Math.min(Math.max(v, min), max));
                if (k === 0) g.moveTo(px, py); else g.lineTo(px, py);
            });
            g.stroke();
        });
        if (this.bool(["show_y_axis", "scales"], false)) {
            const d = this.int(["decimals"], 1);
            g.fillStyle = this.cssVar("--text-color", "#333");
            g.font = "10px sans-serif";
            g.fillText(formatNumber(max, d), 2, 10);
            g.fillText(formatNumber(min, d), 2, h - 2);
        }
    }
}
