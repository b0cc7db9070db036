// boxplot: one box per row of the buffer (a vector is one row): median, quartiles, and
// whiskers from the smallest to the largest value, on a value axis that ranges over the data.
// Attributes: source, labels (one per row), fill_color|color, y_min, y_max.
import { CanvasWidget, asRows } from "./widget.js";
import { dataRange, drawAxes } from "./axes.js";

export function quartiles(values) {
    const s = [...values].filter(Number.isFinite).sort((a, b) => a - b);
    if (!s.length) return null;
    const q = (p) => { const i = (s.length - 1) * p, k = Math.floor(i); return s[k] + (s[Math.min(k + 1, s.length - 1)] - s[k]) * (i - k); };
    return { min: s[0], q1: q(0.25), median: q(0.5), q3: q(0.75), max: s[s.length - 1] };
}

export default class Boxplot extends CanvasWidget {
    subscriptions() { const p = this.path("source"); return p ? [{ path: p, format: "raw" }] : []; }

    update(frame) {
        const item = frame.get(this.path("source"));
        if (!item) return;
        this.boxes = asRows(item).map((r) => quartiles(r));
        this.all = item.data;
        this.draw();
    }

    draw() {
        if (!this.boxes || !this.fit()) return;
        const n = this.boxes.length, labels = this.list(["labels"], []);
        const fixed = (k) => (this.raw([k]) === undefined ? undefined : this.num([k]));
        const ax = drawAxes(this.g, this.width, this.height, [0, n], dataRange(this.all, fixed("y_min"), fixed("y_max")), {
            color: this.cssVar("--text-color", "#333"), grid: this.cssVar("--grid-color", "#ddd"),
            xTicks: this.boxes.map((_, i) => [i + 0.5, labels[i] ?? String(i)]) });
        const g = this.g, fills = this.colors(["fill_color", "color"]);
        this.boxes.forEach((b, i) => {
            if (!b) return;
            const x = ax.x(i + 0.5), half = Math.max(3, (ax.x(1) - ax.x(0)) * 0.3);
            g.strokeStyle = this.cssVar("--text-color", "#333");
            g.fillStyle = fills[i % fills.length];
            g.beginPath(); g.moveTo(x, ax.y(b.min)); g.lineTo(x, ax.y(b.max)); g.stroke();
            g.fillRect(x - half, ax.y(b.q3), 2 * half, ax.y(b.q1) - ax.y(b.q3));
            g.strokeRect(x - half, ax.y(b.q3), 2 * half, ax.y(b.q1) - ax.y(b.q3));
            g.lineWidth = 2;
            g.beginPath(); g.moveTo(x - half, ax.y(b.median)); g.lineTo(x + half, ax.y(b.median)); g.stroke();
            g.lineWidth = 1;
        });
    }
}
