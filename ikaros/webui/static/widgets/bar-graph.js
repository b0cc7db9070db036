// bar-graph: one bar per element, one group of bars per row, on a value axis with tick
// labels (drawn by axes.js, as the scatter plot, histogram and boxplot are).
// Attributes: source, direction|orientation (vertical/horizontal), transpose, labels (on
// the category axis), color|stroke_color, fill|fill_color (comma lists cycle per bar),
// lineWidth|line_width, min|y_min, max|y_max (without both, the range follows the data,
// with 0), auto|auto_range (widen a given range to the data), include_zero, unit (the value
// axis's label), show_axis (yes; no: the bars fill the widget), decimals, show_values.
import { CanvasWidget, asRows, formatNumber } from "./widget.js";
import { dataRange, drawAxes, mapping } from "./axes.js";
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
        const textColor = this.cssVar("--text-color", "#333");
        // bar k of row r sits in slot pos .. pos + 1 of the category axis (half a slot between rows)
        const bars = [];
        let pos = 0;
        this.rows.forEach((row, r) => {
            row.forEach((v) => { bars.push({ v, pos }); pos += 1; });
            if (r < this.rows.length - 1) pos += 0.5;
        });
        const slots = Math.max(pos, 1);
        const categories = labels.length ? bars.map((b, k) => [b.pos + 0.5, labels[k % labels.length]]) : [];
        const values = [min, max];
        // categories run left to right, or top to bottom when horizontal
        const cat = (p) => (horizontal ? slots - p : p);
        let ax;
        if (this.bool(["show_axis"], true)) {
            const unit = this.str(["unit"]);
            const flip = categories.map(([p, t]) => [cat(p), t]);
            ax = horizontal
                ? drawAxes(g, w, h, values, [0, slots], { color: textColor, grid: this.cssVar("--grid-color", "#ddd"), xLabel: unit, yTicks: flip })
                : drawAxes(g, w, h, [0, slots], values, { color: textColor, grid: this.cssVar("--grid-color", "#ddd"), yLabel: unit, xTicks: flip });
        } else {
            ax = horizontal ? mapping({ left: 0, top: 0, right: w, bottom: h }, values, [0, slots])
                : mapping({ left: 0, top: 0, right: w, bottom: h }, [0, slots], values);
        }
        const clamp = (v) => Math.min(Math.max(v, min), max);
        const zero = clamp(0);
        this.lineStyle(g);
        g.font = "10px sans-serif";
        bars.forEach(({ v, pos: p }, k) => {
            // the bar's rectangle: value edges a, b and category edges c, d, in pixels
            const a = horizontal ? ax.x(clamp(v)) : ax.y(clamp(v));
            const b = horizontal ? ax.x(zero) : ax.y(zero);
            const c = horizontal ? ax.y(cat(p + 0.1)) : ax.x(cat(p + 0.1));
            const d = horizontal ? ax.y(cat(p + 0.9)) : ax.x(cat(p + 0.9));
            const rect = horizontal ? [Math.min(a, b), Math.min(c, d), Math.abs(a - b), Math.abs(c - d)]
                : [Math.min(c, d), Math.min(a, b), Math.abs(c - d), Math.abs(a - b)];
            g.fillStyle = fills[k % fills.length];
            g.fillRect(...rect);
            if (strokes.length) { g.strokeStyle = strokes[k % strokes.length]; g.strokeRect(...rect); }
            if (this.bool(["show_values"], false)) {
                const text = formatNumber(v, decimals < 0 ? 2 : decimals);
                g.fillStyle = textColor;
                if (horizontal) { g.textAlign = "left"; g.textBaseline = "middle"; g.fillText(text, Math.max(a, b) + 2, (c + d) / 2); }
                else { g.textAlign = "center"; g.textBaseline = "alphabetic"; g.fillText(text, (c + d) / 2, Math.max(10, Math.min(a, b) - 2)); }
            }
        });
        // the zero line (the bars' base), drawn even when every bar is 0
        g.strokeStyle = this.cssVar("--muted-color", "#888");
        g.lineWidth = 1;
        g.beginPath();
        const { left, top, right, bottom } = ax.box;
        if (horizontal) { g.moveTo(ax.x(zero), top); g.lineTo(ax.x(zero), bottom); }
        else { g.moveTo(left, ax.y(zero)); g.lineTo(right, ax.y(zero)); }
        g.stroke();
    }
}
