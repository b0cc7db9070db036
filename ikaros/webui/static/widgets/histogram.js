// histogram: the distribution of a buffer's values in bins, on axes. The range is the
// data's unless histogram_min / histogram_max (numbers) are given.
// Attributes: source, bins (10), histogram_min, histogram_max, fill_color|color, x_label.
import { CanvasWidget } from "./widget.js";
import { dataRange, drawAxes } from "./axes.js";

export function binCounts(values, bins, lo, hi) {
    const counts = new Array(bins).fill(0);
    for (const v of values) {
        if (!Number.isFinite(v) || v < lo || v > hi) continue;
        counts[Math.min(bins - 1, Math.floor(((v - lo) / (hi - lo || 1)) * bins))]++;
    }
    return counts;
}

export default class Histogram extends CanvasWidget {
    subscriptions() { const p = this.path("source"); return p ? [{ path: p, format: "raw" }] : []; }

    update(frame) {
        const item = frame.get(this.path("source"));
        if (!item) return;
        this.values = item.data;
        this.draw();
    }

    draw() {
        if (!this.values || !this.fit()) return;
        const bins = Math.max(1, this.int(["bins"], 10));
        const fixedLo = this.raw(["histogram_min"]) === undefined ? undefined : this.num(["histogram_min"]);
        const fixedHi = this.raw(["histogram_max"]) === undefined ? undefined : this.num(["histogram_max"]);
        let [lo, hi] = dataRange(this.values, fixedLo, fixedHi);
        this.counts = binCounts(this.values, bins, lo, hi);
        const ax = drawAxes(this.g, this.width, this.height, [lo, hi], [0, Math.max(1, ...this.counts) * 1.05], {
            color: this.cssVar("--text-color", "#333"), grid: this.cssVar("--grid-color", "#ddd"), xLabel: this.str(["x_label"]) });
        this.g.fillStyle = this.colors(["fill_color", "color"])[0];
        this.counts.forEach((c, i) => {
            const x0 = ax.x(lo + (i / bins) * (hi - lo)), x1 = ax.x(lo + ((i + 1) / bins) * (hi - lo));
            this.g.fillRect(x0 + 0.5, ax.y(c), Math.max(1, x1 - x0 - 1), ax.y(0) - ax.y(c));
        });
    }
}
