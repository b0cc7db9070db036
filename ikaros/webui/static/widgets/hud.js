// Heads-up displays drawn over a camera image or a world view (see-through when placed
// over another widget):
// - navigation-hud: a compass tape of the heading (heading_source, degrees, or radians with
//   unit="radians") with the target bearing (target_source) marked;
// - pan-tilt-hud: cross-hairs at the pan and tilt (source: pan, tilt in degrees) within
//   pan_range / tilt_range (default -90..90, -45..45), with the target (target_source).
// Attributes: heading_source | source, target_source, unit, pan_range, tilt_range, color.
import { CanvasWidget } from "./widget.js";

export class Hud extends CanvasWidget {
    subscriptions() {
        return ["source", "heading_source", "target_source"].map((a) => this.path(a)).filter(Boolean).map((path) => ({ path, format: "raw" }));
    }

    update(frame) {
        const main = frame.get(this.path("heading_source", "source")), target = frame.get(this.path("target_source"));
        if (!main) return;
        this.value = [...main.data];
        this.target = target ? [...target.data] : null;
        this.draw();
    }

    degrees(v) { return this.str(["unit"], "degrees") === "radians" ? (v * 180) / Math.PI : v; }

    colour() { return this.colors(["color", "stroke_color"])[0]; }
}

export class NavigationHud extends Hud {
    draw() {
        if (!this.value || !this.fit()) return;
        const g = this.g, w = this.width, h = this.height, heading = this.degrees(this.value[0]);
        const span = 120, px = w / span, cy = h * 0.25;
        g.strokeStyle = g.fillStyle = this.colour();
        g.font = "10px sans-serif";
        g.textAlign = "center";
        for (let d = Math.ceil((heading - span / 2) / 10) * 10; d <= heading + span / 2; d += 10) {
            const x = w / 2 + (d - heading) * px, major = ((d % 90) + 90) % 90 === 0;
            g.beginPath(); g.moveTo(x, cy - (major ? 8 : 4)); g.lineTo(x, cy + (major ? 8 : 4)); g.stroke();
            const a = ((d % 360) + 360) % 360;
            if (major || a % 30 === 0) g.fillText({ 0: "N", 90: "E", 180: "S", 270: "W" }[a] ?? String(a), x, cy + 20);
        }
        g.beginPath(); g.moveTo(w / 2, cy - 12); g.lineTo(w / 2 - 5, cy - 20); g.lineTo(w / 2 + 5, cy - 20); g.closePath(); g.fill();
        g.fillText(`${Math.round(((heading % 360) + 360) % 360)}°`, w / 2, cy + 34);
        if (this.target) {
            let off = this.degrees(this.target[0]) - heading;
            off = ((off + 540) % 360) - 180;
            const x = Math.max(4, Math.min(w - 4, w / 2 + off * px));
            g.beginPath(); g.arc(x, cy, 5, 0, 2 * Math.PI); g.stroke();
        }
    }
}

export class PanTiltHud extends Hud {
    draw() {
        if (!this.value || !this.fit()) return;
        const g = this.g, w = this.width, h = this.height;
        const [p0, p1] = this.list(["pan_range"], ["-90", "90"]).map(Number), [t0, t1] = this.list(["tilt_range"], ["-45", "45"]).map(Number);
        const x = (p) => ((p - p0) / (p1 - p0 || 1)) * w, y = (t) => h - ((t - t0) / (t1 - t0 || 1)) * h;
        g.strokeStyle = g.fillStyle = this.colour();
        g.globalAlpha = 0.4;
        g.strokeRect(0.5, 0.5, w - 1, h - 1);
        g.beginPath(); g.moveTo(x(0), 0); g.lineTo(x(0), h); g.moveTo(0, y(0)); g.lineTo(w, y(0)); g.stroke();
        g.globalAlpha = 1;
        const px = x(this.degrees(this.value[0])), py = y(this.degrees(this.value[1] ?? 0));
        g.lineWidth = 2;
        g.beginPath(); g.moveTo(px - 10, py); g.lineTo(px + 10, py); g.moveTo(px, py - 10); g.lineTo(px, py + 10); g.stroke();
        g.beginPath(); g.arc(px, py, 6, 0, 2 * Math.PI); g.stroke();
        if (this.target) {
            const tx = x(this.degrees(this.target[0])), ty = y(this.degrees(this.target[1] ?? 0));
            g.lineWidth = 1;
            g.strokeRect(tx - 5, ty - 5, 10, 10);
        }
        g.font = "10px sans-serif";
        g.fillText(`pan ${this.degrees(this.value[0]).toFixed(1)}°  tilt ${this.degrees(this.value[1] ?? 0).toFixed(1)}°`, 4, h - 4);
    }
}
