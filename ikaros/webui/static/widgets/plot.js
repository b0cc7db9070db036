// plot: a time plot of each (selected) element in which every tick is seen. The buffer is
// subscribed as "history": each frame brings every sample since the previous frame, or,
// when the ticks outnumber the plot's pixel columns, the smallest and largest value in each
// column (drawn as a band), so fast signals show what they did instead of aliasing.
// Drawn with uPlot (vendor/uplot): axes with tick labels; the value axis ranges over the
// data unless min and max are given.
// Attributes: source, select|select_x (comma list of element indices), buffer_size (ticks
// shown; 0 or none: as many as the plot is wide in pixels), min|y_min, max|y_max (a fixed
// range; auto|auto_range=yes ranges over the data all the same), include_zero, unit (the
// value axis's label), x_label (default "tick"), show_x_axis, show_y_axis (yes),
// color|stroke_color (cycles per series), lineWidth|line_width, decimals. A small plot drops
// what of its axes does not fit (plot-layout.js).
import uPlot from "../vendor/uplot/uPlot.esm.js";
import { axesLayout, yValuesWidth } from "./plot-layout.js";
import { Widget } from "./widget.js";

// steps between the tick labels of the x axis: whole ticks only
const TICK_STEPS = [1, 2, 5].flatMap((m) => [1, 10, 100, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8].map((p) => m * p)).sort((a, b) => a - b);

let cssAdded = false;
function addCss() {
    if (cssAdded) return;
    cssAdded = true;
    const link = document.createElement("link");
    link.rel = "stylesheet";
    link.href = new URL("../vendor/uplot/uPlot.min.css", import.meta.url).href;
    document.head.appendChild(link);
}

/** An rgba() text of a CSS colour with another alpha. */
function withAlpha(color, alpha) {
    const c = document.createElement("canvas").getContext("2d");
    c.fillStyle = color;
    const hex = c.fillStyle;
    if (!hex.startsWith("#")) return hex;
    const n = parseInt(hex.slice(1), 16);
    return `rgba(${n >> 16}, ${(n >> 8) & 255}, ${n & 255}, ${alpha})`;
}

export default class Plot extends Widget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        addCss();
        this.xs = [];              // ticks
        this.lo = [];              // per series: the smallest value at each x
        this.hi = [];              // per series: the largest
        this.sel = null;
        this.plot = null;
        this.resizer = new ResizeObserver(() => this.resize());
        this.resizer.observe(this.body);
    }

    /** Per plotted element, its values in order (the largest of each envelope column). */
    get series() { return this.hi; }

    subscriptions() {
        const p = this.path("source");
        if (!p) return [];
        const points = Math.min(8192, Math.max(16, Math.round(this.body.clientWidth) || 512));
        // the latest ticks shown: a page opened or reloaded late gets those, every sample
        // of them when they fit the plot's columns, not an envelope of the whole history
        return [{ path: p, format: "history", points, ticks: Math.min(16384, this.window()) }];
    }

    /** Ticks shown: buffer_size, or the width in pixels. */
    window() {
        return this.int(["buffer_size"], 0) || Math.max(10, Math.round(this.body.clientWidth) || 500);
    }

    selection(n) {
        const sel = this.list(["select", "select_x"], []).filter((s) => s !== "").map((s) => parseInt(s, 10)).filter((i) => i >= 0 && i < n);
        return sel.length ? sel : Array.from({ length: n }, (_, i) => i);
    }

    reset(n) {
        this.sel = this.selection(n);
        this.n = n;
        this.xs = [];
        this.lo = this.sel.map(() => []);
        this.hi = this.sel.map(() => []);
        this.plot?.destroy();
        this.plot = null;
    }

    /** Append samples (x, element -> lo, element -> hi) after dropping any at or after x. */
    append(x, lo, hi) {
        while (this.xs.length && this.xs[this.xs.length - 1] >= x) {
            this.xs.pop();
            for (const s of this.lo) s.pop();
            for (const s of this.hi) s.pop();
        }
        this.xs.push(x);
        this.sel.forEach((e, i) => { this.lo[i].push(lo(e)); this.hi[i].push(hi(e)); });
    }

    update(frame) {
        const path = this.path("source");
        const item = frame.get(path, "history");
        if (item) {
            const shape = item.buffer_shape || [];
            const n = shape.reduce((a, b) => a * b, 1);
            if (this.n !== n || (item.ticks.length && this.xs.length && item.ticks[0] < this.xs[0])) this.reset(n);
            const d = item.data;
            item.ticks.forEach((t, j) => {
                if (item.mode === "envelope") this.append(t, (e) => d[(2 * j) * n + e], (e) => d[(2 * j + 1) * n + e]);
                else this.append(t, (e) => d[j * n + e], (e) => d[j * n + e]);
            });
            this.seenHistory = true;
        } else {
            const raw = frame.get(path);            // a one-off read before any history
            if (!raw || this.seenHistory || typeof frame.tick !== "number") return;
            if (this.n !== raw.data.length) this.reset(raw.data.length);
            this.append(frame.tick, (e) => raw.data[e], (e) => raw.data[e]);
        }
        if (!this.xs.length) return;
        const from = this.xs[this.xs.length - 1] - this.window();
        let k = 0;
        while (k < this.xs.length && this.xs[k] <= from) k++;
        if (k) {
            this.xs.splice(0, k);
            for (const s of [...this.lo, ...this.hi]) s.splice(0, k);
        }
        this.draw();
    }

    options(w, h) {
        const colors = this.colors(["color", "stroke_color"]);
        const text = this.cssVar("--text-color", "#333"), grid = this.cssVar("--grid-color", "#ddd");
        const width = this.num(["lineWidth", "line_width"], 1.5);
        const series = [{}], bands = [];
        this.sel.forEach((e, i) => {
            const stroke = colors[i % colors.length];
            series.push({ label: `[${e}]`, stroke, width }, { label: `[${e}] max`, stroke, width });
            bands.push({ series: [2 + 2 * i, 1 + 2 * i], fill: withAlpha(stroke, 0.3) });
        });
        const fixed = this.raw(["min", "y_min"]) !== undefined && this.raw(["max", "y_max"]) !== undefined
            && !this.bool(["auto", "auto_range"], false);
        const includeZero = this.bool(["include_zero"], false);
        const decimals = this.int(["decimals"], -1);
        const layout = this.layout(w, h);
        const axis = (show, values, label, size) => ({
            show: show && (values || label !== undefined), stroke: text, label,
            labelSize: label !== undefined ? layout.titleSize : 0, labelGap: 0,
            labelFont: "10px sans-serif", font: "10px sans-serif", size: values ? size : 0,
            gap: values ? 5 : 0,
            grid: { stroke: grid, width: 0.5 }, ticks: { show: values, stroke: grid, width: 0.5, size: 3 },
            ...(values ? {} : { values: (u, splits) => splits.map(() => "") }),
        });
        const xAxis = axis(this.bool(["show_x_axis"], true), layout.xValues,
            layout.xTitle ? this.str(["x_label"], "tick") : undefined, layout.xSize);
        xAxis.incrs = TICK_STEPS;
        // room for each tick value: its text and a gap, at most 50 px
        xAxis.space = (u, i, lo, hi, dim) => Math.min(50, Math.max(dim / 2.5,
            u.ctx.measureText(Math.round(hi).toLocaleString()).width / (u.pxRatio || 1) + 10));
        const unit = this.str(["unit"]);
        const yAxis = axis(this.bool(["show_y_axis"], true), layout.yValues,
            layout.yTitle && unit ? unit : undefined, 0);
        if (layout.yValues) yAxis.size = (u, values) => yValuesWidth(values || []);
        // a low plot still labels a few values (uPlot's 30 px would leave one or none)
        yAxis.space = (u, i, lo, hi, dim) => Math.max(12, Math.min(30, dim / 3));
        if (decimals >= 0 && layout.yValues) yAxis.values = (u, vals) => vals.map((v) => v.toFixed(decimals));
        return {
            width: w, height: h, legend: { show: false }, cursor: { show: true, drag: { x: false, y: false } },
            series, bands, pxAlign: 0, padding: layout.padding,
            scales: {
                x: { time: false, range: () => this.tickRange() },
                y: fixed ? { range: [this.num(["min", "y_min"]), this.num(["max", "y_max"])] }
                    : { range: (u, lo, hi) => this.autoRange(lo, hi, includeZero) },
            },
            axes: [xAxis, yAxis],
        };
    }

    /** What of the axes fits a w x h plot (plot-layout.js). */
    layout(w, h) {
        return axesLayout(w, h, {
            xAxis: this.bool(["show_x_axis"], true), yAxis: this.bool(["show_y_axis"], true),
            xTitle: this.str(["x_label"], "tick") !== "", yTitle: this.str(["unit"]) !== "",
        });
    }

    /** The last buffer_size ticks, or from the first sample while there are fewer; taken
     *  from the ticks held (uPlot widens a single tick t to 0..2t before asking). */
    tickRange() {
        if (!this.xs.length) return [0, 1];
        const last = this.xs[this.xs.length - 1];
        if (this.xs.length === 1) return [last - 1, last + 1];
        return [Math.max(this.xs[0], last - this.window()), last];
    }

    /** The data's range, widened a little; a flat signal gets a unit-wide range. */
    autoRange(lo, hi, includeZero) {
        if (lo === null || hi === null || !Number.isFinite(lo) || !Number.isFinite(hi)) return [0, 1];
        if (includeZero) { lo = Math.min(lo, 0); hi = Math.max(hi, 0); }
        if (hi - lo < 1e-9) return [lo - 0.5, hi + 0.5];
        const pad = (hi - lo) * 0.05;
        return uPlot.rangeNum(lo - pad, hi + pad, 0, true);
    }

    data() {
        const out = [this.xs];
        this.sel.forEach((_, i) => out.push(this.lo[i], this.hi[i]));
        return out;
    }

    draw() {
        const w = this.body.clientWidth, h = this.body.clientHeight;
        if (!w || !h || !this.sel) return;
        if (!this.plot) this.plot = new uPlot(this.options(w, h), this.data(), this.body);
        else this.plot.setData(this.data());
    }

    resize() {
        if (!this.plot) { this.draw(); return; }     // shown at last (a view opened hidden)
        const w = this.body.clientWidth, h = this.body.clientHeight;
        if (!w || !h || (w === this.plot.width && h === this.plot.height)) return;
        const before = this.layout(this.plot.width, this.plot.height), now = this.layout(w, h);
        if (["xValues", "xTitle", "yValues", "yTitle"].every((k) => before[k] === now[k])) {
            this.plot.setSize({ width: w, height: h });
        } else {                                    // other parts of the axes fit now
            this.plot.destroy();
            this.plot = null;
            this.draw();
        }
    }

    destroy() {
        this.resizer.disconnect();
        this.plot?.destroy();
    }
}
