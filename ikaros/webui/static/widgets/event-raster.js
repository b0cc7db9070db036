// event-raster: a spike or event raster. The buffer is subscribed as "events", so every
// (tick, element) whose value is above 0 arrives, however fast the model runs: none is
// lost between frames. One row per element, one mark per event.
// Attributes: source, history (ticks shown; default the width in pixels), color|stroke_color
// (cycles per row), labels (comma list, one per row), show_labels.
import { CanvasWidget } from "./widget.js";
import { drawAxes } from "./axes.js";

export default class EventRaster extends CanvasWidget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        this.events = [];          // [tick, element]
        this.last = -1;
        this.channels = 0;
        this.count = 0;            // events received in all
    }

    subscriptions() { const p = this.path("source"); return p ? [{ path: p, format: "events" }] : []; }

    window() { return this.int(["history"], 0) || Math.max(10, Math.round(this.body.clientWidth) || 500); }

    update(frame) {
        const item = frame.get(this.path("source"), "events");
        if (!item) return;
        this.channels = (item.buffer_shape || [1]).reduce((a, b) => a * b, 1);
        if (item.last_tick < this.last) { this.events = []; this.count = 0; }   // a new network
        const d = item.data;
        for (let i = 0; i + 1 < d.length; i += 2) this.events.push([item.first_tick + d[i], d[i + 1]]);
        this.count += d.length / 2;
        this.missed = (this.missed || 0) + (item.missed || 0);     // ticks the ring lost
        this.last = item.last_tick;
        const from = this.last - this.window();
        let k = 0;
        while (k < this.events.length && this.events[k][0] <= from) k++;
        if (k) this.events.splice(0, k);
        this.draw();
    }

    draw() {
        if (!this.fit()) return;
        const g = this.g, n = Math.max(1, this.channels), to = Math.max(this.last, 1), from = Math.max(0, to - this.window());
        const labels = this.list(["labels"], []);
        const axes = drawAxes(g, this.width, this.height, [from, to], [0, n], {
            color: this.cssVar("--text-color", "#333"), grid: this.cssVar("--grid-color", "#ddd"), xLabel: "tick", yLabel: "element" });
        const ax = { ...axes, y: (e) => axes.y(n - e) };     // element 0 on top
        const colors = this.colors(["color", "stroke_color"]);
        const rowH = Math.max(1, (ax.box.bottom - ax.box.top) / n);
        g.lineWidth = Math.max(1, (ax.box.right - ax.box.left) / this.window());
        for (const [t, e] of this.events) {
            const x = ax.x(t), y = ax.y(e);
            g.strokeStyle = colors[e % colors.length];
            g.beginPath(); g.moveTo(x, y + 1); g.lineTo(x, y + rowH - 1); g.stroke();
        }
        if (labels.length) {
            g.fillStyle = this.cssVar("--text-color", "#333");
            g.font = "9px sans-serif";
            labels.forEach((l, i) => g.fillText(l, ax.box.left + 2, ax.y(i) + rowH / 2 + 3));
        }
    }
}
