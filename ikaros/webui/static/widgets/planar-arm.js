// planar-arm: a PlanarArm module drawn live: its links and joints, the target and the hand,
// in the unit square with y up (the base stands at (0.5, 0) on the bottom edge).
//
// Attributes:
//   module          the PlanarArm module, as a path from the widget's group (module="Arm");
//                   the widget reads its outputs MODULE.JOINTS, MODULE.TARGET and
//                   MODULE.HAND_POSITION and its parameter target_size
//   joints_source   the joint positions instead of MODULE.JOINTS (one (x, y) row per joint,
//                   from the base to the hand)
//   target_source   the target (x, y) instead of MODULE.TARGET ("none": no target)
//   hand_source     the hand (x, y) instead of MODULE.HAND_POSITION (default: the last joint)
//   target_size     the target's radius in world units (default: the module's target_size,
//                   the distance that counts as contact; 0.05)
//   hand_size       the hand's radius in world units (default 0.025)
//   link_width      the links' width in pixels (default 6)
//   trail           how many past hand positions to draw as a line (default 0: none)
//   x_min, x_max, y_min, y_max  the world shown (default 0..1 both); the aspect is kept
//   link_color, joint_color, base_color, target_color, hand_color, trail_color,
//   area_color (the square x_min..x_max, y_min..y_max)   the colours (CSS)
// and the base's title, show_title, show_frame|frame, frame_color, frame_width,
// background, style.
import { ModuleWidget, asRows } from "./widget.js";

export const COLORS = {
    area: "#f4f3ee", link: "#3f4654", joint: "#8a93a3", base: "#222831",
    target: "#d83a2e", hand: "#1f6fd0", trail: "rgba(31, 111, 208, 0.35)",
};

/** World (y up) to canvas mapping with the aspect kept, centred, with a margin in pixels. */
export function worldMapping(width, height, xmin, xmax, ymin, ymax, margin = 4) {
    const w = Math.max(1, width - 2 * margin), h = Math.max(1, height - 2 * margin);
    const scale = Math.min(w / (xmax - xmin || 1), h / (ymax - ymin || 1));
    const ox = (width - (xmax - xmin) * scale) / 2, oy = (height - (ymax - ymin) * scale) / 2;
    return {
        scale,
        x: (x) => ox + (x - xmin) * scale,
        y: (y) => oy + (ymax - y) * scale,
        box: [ox, oy, (xmax - xmin) * scale, (ymax - ymin) * scale],
    };
}

export default class PlanarArm extends ModuleWidget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        this.targetSize = 0.05;
        this.trail = [];
    }

    paths() {
        return {
            joints: this.buffer("joints", "JOINTS"),
            target: this.buffer("target", "TARGET"),
            hand: this.buffer("hand", "HAND_POSITION"),
        };
    }

    subscriptions() {
        return Object.values(this.paths()).filter(Boolean).map((path) => ({ path, format: "raw" }));
    }

    parameters() { return this.module ? [`${this.module}.target_size`] : []; }

    setParameters(values) {
        const v = Number(values.get(`${this.module}.target_size`));
        if (Number.isFinite(v) && v > 0 && v !== this.targetSize) { this.targetSize = v; this.draw(); }
    }

    update(frame) {
        const p = this.paths();
        const get = (path) => (path ? frame.get(path) : undefined);
        const joints = get(p.joints), target = get(p.target), hand = get(p.hand);
        if (joints) this.joints = asRows(joints).filter((r) => r.length >= 2).map((r) => ({ x: r[0], y: r[1] }));
        if (target && target.data.length >= 2) this.target = { x: target.data[0], y: target.data[1] };
        if (hand && hand.data.length >= 2) this.hand = { x: hand.data[0], y: hand.data[1] };
        else if (this.joints?.length) this.hand = this.joints[this.joints.length - 1];
        const n = this.int(["trail"], 0);
        if (n > 0 && this.hand && frame.tick !== this.lastTick) {
            this.trail.push({ ...this.hand });
            while (this.trail.length > n) this.trail.shift();
        }
        this.lastTick = frame.tick;
        this.draw();
    }

    mapping() {
        return worldMapping(this.width, this.height, this.num(["x_min", "min_x"], 0), this.num(["x_max", "max_x"], 1),
            this.num(["y_min", "min_y"], 0), this.num(["y_max", "max_y"], 1));
    }

    resize() { this.draw(); }

    draw() {
        if (!(this.joints || this.target) || !this.fit()) return;
        const g = this.g, m = this.mapping();
        const color = (name) => this.str([name + "_color"], COLORS[name]);
        g.fillStyle = color("area");
        g.fillRect(...m.box);
        const disc = (p, radius, fill) => {
            g.fillStyle = fill;
            g.beginPath();
            g.arc(m.x(p.x), m.y(p.y), radius, 0, 2 * Math.PI);
            g.fill();
        };
        if (this.trail.length > 1) {
            g.strokeStyle = color("trail");
            g.lineWidth = 2;
            g.beginPath();
            this.trail.forEach((p, i) => (i ? g.lineTo(m.x(p.x), m.y(p.y)) : g.moveTo(m.x(p.x), m.y(p.y))));
            g.stroke();
        }
        const linkWidth = this.num(["link_width"], 6);
        if (this.joints && this.joints.length) {
            const base = this.joints[0];
            // the base: a half disc on the floor
            g.fillStyle = color("base");
            g.beginPath();
            g.arc(m.x(base.x), m.y(base.y), linkWidth * 2, Math.PI, 2 * Math.PI);
            g.fill();
            g.strokeStyle = color("link");
            g.lineWidth = linkWidth;
            g.lineCap = "round";
            g.lineJoin = "round";
            g.beginPath();
            this.joints.forEach((p, i) => (i ? g.lineTo(m.x(p.x), m.y(p.y)) : g.moveTo(m.x(p.x), m.y(p.y))));
            g.stroke();
            for (const p of this.joints.slice(0, -1)) disc(p, linkWidth * 0.8, color("joint"));
        }
        if (this.target) {
            disc(this.target, Math.max(3, this.num(["target_size"], this.targetSize) * m.scale), color("target"));
        }
        if (this.hand) disc(this.hand, Math.max(3, this.num(["hand_size"], 0.025) * m.scale), color("hand"));
    }
}
