// epi-head: a drawing of the Epi robot's head: two eyes whose irises follow the gaze and
// whose pupils open with the pupil size, and a mouth.
// Attributes: eye_direction_source|gazeSource (x, y: -1..1, or the head's pan and tilt in
// degrees when gaze_in_degrees=yes, each then divided by 30), pupil_size_source (one value
// for both eyes or two: left, right; 0..1) or pupilLeftSource/pupilRightSource, eye_color
// (iris), mouth_color, head_color, gaze, vergence (fixed values when there is no source).
import { CanvasWidget } from "./widget.js";

export default class EpiHead extends CanvasWidget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        this.gaze = [this.num(["gaze"], 0), 0];
        this.pupils = [0.5, 0.5];
    }

    subscriptions() {
        return ["eye_direction_source", "gazeSource", "pupil_size_source", "pupilLeftSource", "pupilRightSource"]
            .map((a) => this.path(a)).filter(Boolean).map((path) => ({ path, format: "raw" }));
    }

    update(frame) {
        const gaze = frame.get(this.path("eye_direction_source", "gazeSource"));
        if (gaze) {
            const k = this.bool(["gaze_in_degrees"], false) ? 1 / 30 : 1;
            this.gaze = [gaze.data[0] * k, (gaze.data[1] ?? 0) * k].map((v) => Math.max(-1, Math.min(1, v)));
        }
        const pupil = frame.get(this.path("pupil_size_source"));
        if (pupil) this.pupils = [pupil.data[0], pupil.data[1] ?? pupil.data[0]];
        const l = frame.get(this.path("pupilLeftSource")), r = frame.get(this.path("pupilRightSource"));
        if (l) this.pupils[0] = l.data[0];
        if (r) this.pupils[1] = r.data[0];
        this.draw();
    }

    draw() {
        if (!this.fit()) return;
        const g = this.g, w = this.width, h = this.height, s = Math.min(w, h) / 2;
        const cx = w / 2, cy = h / 2;
        g.fillStyle = this.str(["head_color"], "#e8e6e1");
        g.strokeStyle = this.cssVar("--text-color", "#333");
        g.beginPath(); g.ellipse(cx, cy, s * 0.9, s * 0.95, 0, 0, 2 * Math.PI); g.fill(); g.stroke();
        const vergence = this.num(["vergence"], 0);
        const iris = this.str(["eye_color"], "#2a7ab9");
        [-1, 1].forEach((side, i) => {
            const ex = cx + side * s * 0.38, ey = cy - s * 0.2, er = s * 0.24;
            g.fillStyle = "#fff";
            g.beginPath(); g.arc(ex, ey, er, 0, 2 * Math.PI); g.fill(); g.stroke();
            const gx = this.gaze[0] - side * vergence * 0.2, gy = this.gaze[1];
            const ix = ex + gx * er * 0.45, iy = ey - gy * er * 0.45, ir = er * 0.55;
            g.fillStyle = iris;
            g.beginPath(); g.arc(ix, iy, ir, 0, 2 * Math.PI); g.fill();
            const p = Math.max(0.1, Math.min(1, this.pupils[i] ?? 0.5));
            g.fillStyle = "#111";
            g.beginPath(); g.arc(ix, iy, ir * (0.25 + 0.65 * p), 0, 2 * Math.PI); g.fill();
        });
        g.strokeStyle = this.str(["mouth_color"], "#c0392b");
        g.lineWidth = Math.max(2, s * 0.05);
        g.beginPath(); g.arc(cx, cy + s * 0.25, s * 0.3, 0.2 * Math.PI, 0.8 * Math.PI); g.stroke();
        g.lineWidth = 1;
    }
}
