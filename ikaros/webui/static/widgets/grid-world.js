// grid-world: a GridWorld module's world drawn live: free cells, walls, rewards, and the
// agent as a disc with a pointer for its heading.
//
// Attributes:
//   module             the GridWorld module, as a path from the widget's group
//                      (module="World"); the widget reads its outputs MODULE.IMAGE,
//                      MODULE.COORDINATE and MODULE.HEADING and its parameters radius and
//                      normalize_coordinate
//   image_source       the picture of the world instead of MODULE.IMAGE (0 free, 1/3 wall,
//                      2/3 agent, 1 reward)
//   obstacles_source   walls from this matrix instead (cells of 1 or more), e.g. the buffer
//                      connected to the module's OBSTACLES input
//   values_source      rewards from this matrix (cells > 0; cells < 0 are punishments), e.g.
//                      the buffer connected to VALUES; used with obstacles_source
//   coordinate_source  the agent's (x = column, y = row) instead of MODULE.COORDINATE;
//                      a cell's centre is at its integer coordinate
//   heading_source     the heading (radians clockwise from north = up) instead of
//                      MODULE.HEADING
//   agent_radius       the agent's radius in cells (default: the module's radius, 0.3)
//   show_heading       draw the heading pointer (default yes)
//   border             draw the outer cells as walls, as the module treats them (default yes)
//   grid_lines         thin lines between the cells (default yes)
//   free_color, wall_color, reward_color, punishment_color, agent_color, heading_color,
//   grid_color         the colours (CSS)
// and the base's title, show_title, show_frame|frame, frame_color, frame_width,
// background, style. Cells are square and the world is centred in the widget.
import { ModuleWidget, asRows } from "./widget.js";

export const COLORS = {
    free: "#f4f3ee", wall: "#3f4654", reward: "#f0a81c", punishment: "#c8322d",
    agent: "#1f6fd0", heading: "#ffffff", grid: "rgba(0, 0, 0, 0.12)",
};

export default class GridWorld extends ModuleWidget {
    static defaultTitle = "";

    constructor(attrs, ctx) {
        super(attrs, ctx);
        this.params = { radius: 0.3, normalize_coordinate: false };
    }

    paths() {
        const separate = !!this.path("obstacles_source");
        return {
            image: separate ? "" : this.buffer("image", "IMAGE"),
            obstacles: separate ? this.path("obstacles_source") : "",
            values: separate ? this.path("values_source") : "",
            coordinate: this.buffer("coordinate", "COORDINATE"),
            heading: this.buffer("heading", "HEADING"),
        };
    }

    subscriptions() {
        return Object.values(this.paths()).filter(Boolean).map((path) => ({ path, format: "raw" }));
    }

    parameters() {
        return this.module ? ["radius", "normalize_coordinate"].map((p) => `${this.module}.${p}`) : [];
    }

    setParameters(values) {
        let changed = false;
        for (const name of Object.keys(this.params)) {
            const v = values.get(`${this.module}.${name}`);
            if (v !== undefined && v !== this.params[name]) { this.params[name] = v; changed = true; }
        }
        if (changed) this.draw();
    }

    update(frame) {
        const p = this.paths();
        const get = (path) => (path ? frame.get(path) : undefined);
        const image = get(p.image), obstacles = get(p.obstacles), values = get(p.values);
        if (image) this.cells = asRows(image).map((row) => Array.from(row, classifyImage));
        else if (obstacles) {
            const vrows = values ? asRows(values) : null;
            this.cells = asRows(obstacles).map((row, r) => Array.from(row, (o, c) => {
                if (o >= 1) return "wall";
                const v = vrows?.[r]?.[c] ?? 0;
                return v > 0 ? "reward" : v < 0 ? "punishment" : "free";
            }));
        }
        const coord = get(p.coordinate);
        if (coord && coord.data.length >= 2) this.agent = { x: coord.data[0], y: coord.data[1] };
        const heading = get(p.heading);
        if (heading && heading.data.length) this.heading = heading.data[0];
        this.draw();
    }

    /** Cell size and origin of the centred square cells (CSS pixels). */
    layout() {
        const rows = this.cells.length, cols = this.cells[0]?.length || 1;
        const cell = Math.min(this.width / cols, this.height / rows);
        return { rows, cols, cell, ox: (this.width - cols * cell) / 2, oy: (this.height - rows * cell) / 2 };
    }

    resize() { this.draw(); }

    draw() {
        if (!this.cells || !this.cells.length || !this.fit()) return;
        const g = this.g;
        const { rows, cols, cell, ox, oy } = this.layout();
        const color = (name) => this.str([name + "_color"], COLORS[name]);
        const border = this.bool(["border"], true);
        for (let r = 0; r < rows; r++) {
            for (let c = 0; c < cols; c++) {
                let kind = this.cells[r][c];
                if (border && (r === 0 || c === 0 || r === rows - 1 || c === cols - 1)) kind = "wall";
                g.fillStyle = color(kind);
                // a little overlap hides seams between neighbouring cells
                g.fillRect(ox + c * cell, oy + r * cell, cell + 0.5, cell + 0.5);
            }
        }
        if (this.bool(["grid_lines"], true) && cell >= 6) {
            g.strokeStyle = color("grid");
            g.lineWidth = 1;
            g.beginPath();
            for (let c = 1; c < cols; c++) { const x = Math.round(ox + c * cell) + 0.5; g.moveTo(x, oy); g.lineTo(x, oy + rows * cell); }
            for (let r = 1; r < rows; r++) { const y = Math.round(oy + r * cell) + 0.5; g.moveTo(ox, y); g.lineTo(ox + cols * cell, y); }
            g.stroke();
        }
        if (!this.agent) return;
        let { x, y } = this.agent;
        if (this.params.normalize_coordinate === true) { x = x * cols - 0.5; y = y * rows - 0.5; }
        const cx = ox + (x + 0.5) * cell, cy = oy + (y + 0.5) * cell;
        const radius = this.num(["agent_radius"], Number(this.params.radius) > 0 ? Number(this.params.radius) : 0.3);
        const r = Math.max(3, radius * cell);
        g.fillStyle = color("agent");
        g.beginPath();
        g.arc(cx, cy, r, 0, 2 * Math.PI);
        g.fill();
        if (this.heading !== undefined && this.bool(["show_heading"], true)) {
            // clockwise from north (up): the direction on the canvas is (sin h, -cos h)
            drawPointer(g, cx, cy, r, Math.sin(this.heading), -Math.cos(this.heading), color("heading"));
        }
    }
}

/** A picture value of GridWorld.IMAGE as a kind of cell. */
function classifyImage(v) {
    if (v >= 0.99) return "reward";
    if (Math.abs(v - 2 / 3) < 0.05) return "free";      // the agent's cell
    if (v >= 1 / 3 - 0.01) return "wall";
    return "free";
}

/** A heading pointer inside a disc of radius r at (cx, cy): a triangle from near the centre
 *  to the rim in the direction (dx, dy). The centre itself keeps the body's colour. */
export function drawPointer(g, cx, cy, r, dx, dy, color) {
    const px = -dy, py = dx;
    g.fillStyle = color;
    g.beginPath();
    g.moveTo(cx + dx * r * 0.95, cy + dy * r * 0.95);
    g.lineTo(cx + dx * r * 0.15 + px * r * 0.55, cy + dy * r * 0.15 + py * r * 0.55);
    g.lineTo(cx + dx * r * 0.15 - px * r * 0.55, cy + dy * r * 0.15 - py * r * 0.55);
    g.closePath();
    g.fill();
}
