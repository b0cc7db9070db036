// vector-field: an arrow at each cell of a grid, from x_source and y_source (two matrices
// of the same shape) or from source of shape (2, rows, cols). Arrows are scaled so that the
// longest fills a cell (vector_scale multiplies that).
// Attributes: source | x_source + y_source, vector_scale (1), color|stroke_color, stride (1).
import { CanvasWidget } from "./widget.js";

export default class VectorField extends CanvasWidget {
    subscriptions() {
        return ["source", "x_source", "y_source"].map((a) => this.path(a)).filter(Boolean).map((path) => ({ path, format: "raw" }));
    }

    update(frame) {
        const xs = frame.get(this.path("x_source")), ys = frame.get(this.path("y_source")), both = frame.get(this.path("source"));
        if (xs && ys) {
            this.shape = xs.shape.length >= 2 ? xs.shape.slice(-2) : [1, xs.data.length];
            this.u = xs.data; this.v = ys.data;
        } else if (both && both.shape[0] === 2) {
            const n = both.data.length / 2;
            this.shape = both.shape.length >= 3 ? both.shape.slice(-2) : [1, n];
            this.u = both.data.subarray(0, n); this.v = both.data.subarray(n);
        } else return;
        this.draw();
    }

    draw() {
        if (!this.u || !this.fit()) return;
        const [rows, cols] = this.shape, g = this.g, stride = Math.max(1, this.int(["stride"], 1));
        const cw = this.width / cols, ch = this.height / rows;
        let longest = 1e-12;
        for (let i = 0; i < this.u.length; i++) longest = Math.max(longest, Math.hypot(this.u[i], this.v[i]));
        const k = (Math.min(cw, ch) * stride * 0.9 * this.num(["vector_scale"], 1)) / longest;
        g.strokeStyle = g.fillStyle = this.colors(["color", "stroke_color"])[0];
        g.lineWidth = 1.2;
        for (let r = 0; r < rows; r += stride) {
            for (let c = 0; c < cols; c += stride) {
                const i = r * cols + c, x = (c + 0.5) * cw, y = (r + 0.5) * ch;
                const dx = this.u[i] * k, dy = -this.v[i] * k, L = Math.hypot(dx, dy);
                if (L < 0.5) continue;
                const x0 = x - dx / 2, y0 = y - dy / 2, x1 = x + dx / 2, y1 = y + dy / 2, a = Math.atan2(dy, dx), h = Math.min(6, L / 3);
                g.beginPath(); g.moveTo(x0, y0); g.lineTo(x1, y1); g.stroke();
                g.beginPath(); g.moveTo(x1, y1);
                g.lineTo(x1 - h * Math.cos(a - 0.4), y1 - h * Math.sin(a - 0.4));
                g.lineTo(x1 - h * Math.cos(a + 0.4), y1 - h * Math.sin(a + 0.4));
                g.closePath(); g.fill();
            }
        }
    }
}
