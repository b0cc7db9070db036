// world-2d: a World2D module drawn live, seen from above (x to the right, y up, metres):
// the arena's walls and box obstacles, the round objects, the robot with a pointer for its
// heading, and its range-sensor rays with their end points.
//
// Attributes:
//   module           the World2D module, as a path from the widget's group (module="World");
//                    the widget reads its outputs MODULE.POSE, MODULE.OBJECTS, MODULE.WALLS
//                    and MODULE.RANGE_POINTS and its parameters robot_radius, width, height
//   pose_source      the robot's (x, y, heading) instead of MODULE.POSE (heading in radians
//                    counter-clockwise from the x axis)
//   objects_source   object rows (x, y, angle, radius) instead of MODULE.OBJECTS ("none": none)
//   walls_source     wall segments (x0, y0, x1, y1) instead of MODULE.WALLS ("none": none)
//   rays_source      sensor ray end points (x, y) instead of MODULE.RANGE_POINTS ("none":
//                    no rays)
//   robot_radius     the robot's radius in metres (default: the module's robot_radius, 0.15)
//   x_min, x_max, y_min, y_max  the area shown (default: the arena, 0..width x 0..height, from
//                    the module's parameters or else the walls); the aspect is kept
//   show_rays        draw the sensor rays (default yes)
//   wall_width       the walls' line width in pixels (default 3)
//   floor_color, wall_color, obstacle_color, object_color, robot_color, heading_color,
//   ray_color        the colours (CSS)
// and the base's title, show_title, show_frame|frame, frame_color, frame_width,
// background, style.
import { ModuleWidget, asRows } from "./widget.js";
import { worldMapping } from "./planar-arm.js";
import { drawPointer } from "./grid-world.js";

export const COLORS = {
    floor: "#f4f3ee", wall: "#3f4654", obstacle: "#7d8696", object: "#e08a1e",
    robot: "#1f6fd0", heading: "#ffffff", ray: "#d83a2e",
};

export default class World2D extends ModuleWidget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        this.params = { robot_radius: 0.15, width: null, height: null };
    }

    paths() {
        return {
            pose: this.buffer("pose", "POSE"),
            objects: this.buffer("objects", "OBJECTS"),
            walls: this.buffer("walls", "WALLS"),
            rays: this.bool(["show_rays"], true) ? this.buffer("rays", "RANGE_POINTS") : "",
        };
    }

    subscriptions() {
        return Object.values(this.paths()).filter(Boolean).map((path) => ({ path, format: "raw" }));
    }

    parameters() {
        return this.module ? Object.keys(this.params).map((p) => `${this.module}.${p}`) : [];
    }

    setParameters(values) {
        let changed = false;
        for (const name of Object.keys(this.params)) {
            const v = Number(values.get(`${this.module}.${name}`));
            if (values.has(`${this.module}.${name}`) && Number.isFinite(v) && v !== this.params[name]) {
                this.params[name] = v;
                changed = true;
            }
        }
        if (changed) this.draw();
    }

    update(frame) {
        const p = this.paths();
        const get = (path) => (path ? frame.get(path) : undefined);
        const pose = get(p.pose), objects = get(p.objects), walls = get(p.walls), rays = get(p.rays);
        if (pose && pose.data.length >= 3) this.pose = { x: pose.data[0], y: pose.data[1], heading: pose.data[2] };
        if (objects) {
            this.objects = asRows(objects).filter((r) => r.length >= 4 && r[3] > 0)
                .map((r) => ({ x: r[0], y: r[1], angle: r[2], radius: r[3] }));
        }
        if (walls) this.walls = asRows(walls).filter((r) => r.length >= 4).map((r) => [r[0], r[1], r[2], r[3]]);
        if (rays) this.rays = asRows(rays).filter((r) => r.length >= 2).map((r) => ({ x: r[0], y: r[1] }));
        this.draw();
    }

    /** The arena: 0..width x 0..height from the parameters, else the walls' extent. */
    arena() {
        let w = this.params.width, h = this.params.height;
        if (!(w > 0 && h > 0) && this.walls && this.walls.length) {
            w = Math.max(...this.walls.map((s) => Math.max(s[0], s[2])));
            h = Math.max(...this.walls.map((s) => Math.max(s[1], s[3])));
        }
        return { w: w > 0 ? w : 4, h: h > 0 ? h : 3 };
    }

    mapping() {
        const { w, h } = this.arena();
        return worldMapping(this.width, this.height, this.num(["x_min", "min_x"], 0), this.num(["x_max", "max_x"], w),
            this.num(["y_min", "min_y"], 0), this.num(["y_max", "max_y"], h), 4);
    }

    resize() { this.draw(); }

    draw() {
        if (!(this.pose || this.walls) || !this.fit()) return;
        const g = this.g, m = this.mapping();
        const color = (name) => this.str([name + "_color"], COLORS[name]);
        const { w, h } = this.arena();
        g.fillStyle = color("floor");
        g.fillRect(m.x(0), m.y(h), w * m.scale, h * m.scale);
        // obstacles: closed loops of segments other than the arena's edge are filled
        for (const loop of closedLoops(this.walls || [])) {
            const xs = loop.map((s) => s[0]), ys = loop.map((s) => s[1]);
            const isArena = Math.min(...xs) <= 1e-6 && Math.min(...ys) <= 1e-6 &&
                Math.abs(Math.max(...xs) - w) < 1e-4 && Math.abs(Math.max(...ys) - h) < 1e-4;
            if (isArena) continue;
            g.fillStyle = color("obstacle");
            g.beginPath();
            loop.forEach((s, i) => (i ? g.lineTo(m.x(s[0]), m.y(s[1])) : g.moveTo(m.x(s[0]), m.y(s[1]))));
            g.closePath();
            g.fill();
        }
        g.strokeStyle = color("wall");
        g.lineWidth = this.num(["wall_width"], 3);
        g.lineCap = "square";
        g.beginPath();
        for (const [x0, y0, x1, y1] of this.walls || []) { g.moveTo(m.x(x0), m.y(y0)); g.lineTo(m.x(x1), m.y(y1)); }
        g.stroke();
        g.lineCap = "butt";
        for (const o of this.objects || []) {
            const cx = m.x(o.x), cy = m.y(o.y), r = Math.max(2, o.radius * m.scale);
            g.fillStyle = color("object");
            g.beginPath();
            g.arc(cx, cy, r, 0, 2 * Math.PI);
            g.fill();
            // a spoke shows the object's rotation
            g.strokeStyle = "rgba(0, 0, 0, 0.45)";
            g.lineWidth = 1.5;
            g.beginPath();
            g.moveTo(cx, cy);
            g.lineTo(cx + Math.cos(o.angle) * r, cy - Math.sin(o.angle) * r);
            g.stroke();
        }
        if (this.rays && this.pose) {
            g.strokeStyle = color("ray");
            g.fillStyle = color("ray");
            g.globalAlpha = 0.7;
            g.lineWidth = 1;
            g.beginPath();
            for (const p of this.rays) { g.moveTo(m.x(this.pose.x), m.y(this.pose.y)); g.lineTo(m.x(p.x), m.y(p.y)); }
            g.stroke();
            g.globalAlpha = 1;
            for (const p of this.rays) { g.beginPath(); g.arc(m.x(p.x), m.y(p.y), 3, 0, 2 * Math.PI); g.fill(); }
        }
        if (this.pose) {
            const radius = this.num(["robot_radius"], this.params.robot_radius > 0 ? this.params.robot_radius : 0.15);
            const cx = m.x(this.pose.x), cy = m.y(this.pose.y), r = Math.max(4, radius * m.scale);
            g.fillStyle = color("robot");
            g.beginPath();
            g.arc(cx, cy, r, 0, 2 * Math.PI);
            g.fill();
            // counter-clockwise from x with y up: on the canvas (cos h, -sin h)
            drawPointer(g, cx, cy, r, Math.cos(this.pose.heading), -Math.sin(this.pose.heading), color("heading"));
        }
    }
}

/** Chains of segments where each starts at the end of the previous and the last ends at the
 *  start of the first; each chain as its segments. */
function closedLoops(segments) {
    const loops = [];
    const near = (a, b) => Math.abs(a[0] - b[0]) < 1e-5 && Math.abs(a[1] - b[1]) < 1e-5;
    let chain = [];
    for (const s of segments) {
        if (chain.length && !near([chain[chain.length - 1][2], chain[chain.length - 1][3]], s)) chain = [];
        chain.push(s);
        if (chain.length >= 3 && near([s[2], s[3]], chain[0])) { loops.push(chain); chain = []; }
    }
    return loops;
}
