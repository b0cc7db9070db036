// polar-plot: each row of the buffer as a closed line of radii at equal angles (from the
// right, counter-clockwise), with rings of round radii. The radius ranges from 0 to the
// largest value unless max is given.
// Attributes: source, max, labels (one per angle), color|stroke_color (per row), fill (yes).
import { CanvasWidget, asRows } from "./widget.js";
import { niceTicks } from "./axes.js";

export default class PolarPlot extends CanvasWidget {
    subscriptions() { const p = this.path("source"); return p ? [{ path: p, format: "raw" }] : []; }

    update(frame) {
        const item = frame.get(this.path("source"));
        if (!item) return;
        this.rows = asRows(item).map((r) => [...r]);
        this.draw();
    }

    draw() {
        if (!this.rows || !this.fit()) return;
        const g = this.g, cx = this.width / 2, cy = this.height / 2, R = Math.min(cx, cy) - 14;
        const max = this.raw(["max"]) !== undefined ? this.num(["max"]) : Math.max(1e-9, ...this.rows.flat().map(Math.abs));
        const text = this.cssVar("--text-color", "#333"), grid = this.cssVar("--grid-color", "#ddd");
        g.strokeStyle = grid; g.fillStyle = text; g.font = "9px sans-serif";
        for (const v of niceTicks(0, max, 3).filter((v) => v > 0)) {
            g.beginPath(); g.arc(cx, cy, (v / max) * R, 0, 2 * Math.PI); g.stroke();
            g.fillText(String(Math.round(v * 1e6) / 1e6), cx + (v / max) * R + 2, cy - 2);
        }
        const n = Math.max(...this.rows.map((r) => r.length));
        const labels = this.list(["labels"], []);
        for (let i = 0; i < n; i++) {
            const a = (2 * Math.PI * i) / n;
            g.beginPath(); g.moveTo(cx, cy); g.lineTo(cx + R * Math.cos(a), cy - R * Math.sin(a)); g.stroke();
            if (labels[i]) g.fillText(labels[i], cx + (R + 4) * Math.cos(a) - 6, cy - (R + 4) * Math.sin(a) + 3);
        }
        const colors = this.colors(["color", "stroke_color"]);
        this.rows.forEach((r, k) => {
            g.strokeStyle = colors[k % colors.length];
            g.lineWidth = 2;
            g.beginPath();
            r.forEach((v, i) => {
                const a = (2 * Math.PI * i) / r.length, d = (Math.max(0, v) / max) * R;
                if (i === 0) g.moveTo(cx + d * Math.cos(a), cy - d * Math.sin(a)); else g.lineTo(cx + d * Math.cos(a), cy - d * Math.sin(a));
            });
            g.closePath(); g.stroke();
            if (this.bool(["fill"], true)) { g.globalAlpha = 0.2; g.fillStyle = colors[k % colors.length]; g.fill(); g.globalAlpha = 1; }
        });
    }
}
