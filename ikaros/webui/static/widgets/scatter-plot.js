// scatter-plot: points (x[i], y[i]) from two buffers, or from the columns of one (source:
// rows of x,y), on axes that range over the data unless x_min.. y_max are given.
// Attributes: x_source, y_source or source, x_min, x_max, y_min, y_max, x_label, y_label,
// color|stroke_color, size (radius in pixels, 3).
import { CanvasWidget } from "./widget.js";
import { dataRange, drawAxes } from "./axes.js";

export default class ScatterPlot extends CanvasWidget {
    subscriptions() {
        return ["x_source", "y_source", "source"].map((a) => this.path(a)).filter(Boolean).map((path) => ({ path, format: "raw" }));
    }

    update(frame) {
        const xs = frame.get(this.path("x_source")), ys = frame.get(this.path("y_source")), both = frame.get(this.path("source"));
        if (xs && ys) { this.x = [...xs.data]; this.y = [...ys.data]; }
        else if (both) {
            const cols = both.shape.at(-1) || 1;
            this.x = []; this.y = [];
            for (let i = 0; i + 1 < both.data.length; i += cols) { this.x.push(both.data[i]); this.y.push(both.data[i + 1]); }
        } else return;
        this.draw();
    }

    fixed(name) { return this.raw([name]) === undefined ? undefined : this.num([name]); }

    draw() {
        if (!this.x || !this.fit()) return;
        const g = this.g;
        const xr = dataRange(this.x, this.fixed("x_min"), this.fixed("x_max"));
        const yr = dataRange(this.y, this.fixed("y_min"), this.fixed("y_max"));
        const ax = drawAxes(g, this.width, this.height, xr, yr, {
            color: this.cssVar("--text-color", "#333"), grid: this.cssVar("--grid-color", "#ddd"),
            xLabel: this.str(["x_label"]), yLabel: this.str(["y_label"]) });
        const colors = this.colors(["color", "stroke_color"]), r = this.num(["size"], 3);
        this.x.forEach((v, i) => {
            g.fillStyle = colors[0];
            g.beginPath(); g.arc(ax.x(v), ax.y(this.y[i]), r, 0, 2 * Math.PI); g.fill();
        });
    }
}
