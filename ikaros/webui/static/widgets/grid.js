// grid: a matrix as coloured cells (heat map, indicator lamps).
// Attributes: source (or red/green/blue | red_source/green_source/blue_source with rgb),
// fill|color_map (gray/fire/spectrum/red/green/blue/custom/rgb), colorTable|color_map_colors
// (custom), min|value_min, max|value_max, labels (row labels), labelWidth|label_width,
// color|stroke_color (cell outline), lineWidth|line_width, shape (rectangle/square/circle),
// size (cell fill fraction), flips. Control: command (a click sends x, y and
// valueHigh|on_value) or parameter (a click toggles the cell between valueHigh|on_value and
// valueLow|off_value).
import { CanvasWidget, asRows, colorTable, Widget } from "./widget.js";

export default class Grid extends CanvasWidget {
    static defaultTitle = "";

    constructor(attrs, ctx) {
        super(attrs, ctx);
        this.rows = null;
        this.paramValue = null;
        this.canvas.addEventListener("click", (e) => this.click(e));
        if (this.commandTarget("command") || this.path("parameter")) {
            this.canvas.style.cursor = "pointer";
            this.canvas.dataset.control = "";    // a click sets a cell, also in the view editor
        }
    }

    mapName() { return this.str(["fill", "color_map"], this.attrs.class === "heat-map" ? "fire" : "gray"); }

    channelPaths() {
        return ["red", "green", "blue"].map((c) => this.path(c + "_source", c));
    }

    subscriptions() {
        const subs = [];
        if (this.mapName() === "rgb") {
            for (const p of this.channelPaths()) if (p) subs.push({ path: p, format: "raw" });
        }
        const p = this.path("source");
        if (p) subs.push({ path: p, format: "raw" });
        return subs;
    }

    parameters() { const p = this.path("parameter"); return p ? [p] : []; }

    setParameters(values) {
        const p = this.path("parameter");
        if (values.has(p)) this.paramValue = values.get(p);
    }

    update(frame) {
        if (this.mapName() === "rgb" && this.channelPaths().every((p) => p && frame.get(p))) {
            this.channels = this.channelPaths().map((p) => asRows(frame.get(p)));
            this.rows = this.channels[0];
        } else {
            const item = frame.get(this.path("source"));
            if (!item) return;
            this.rows = asRows(item);
            this.channels = null;
        }
        this.draw();
    }

    layout() {
        const labels = this.list(["labels"], []);
        const lw = labels.length ? this.num(["labelWidth", "label_width"], 100) : 0;
        const rows = this.rows.length, cols = this.rows[0]?.length || 1;
        let cw = (this.width - lw) / cols, ch = this.height / rows;
        if (this.str(["shape"], "rectangle") !== "rectangle") cw = ch = Math.min(cw, ch);
        return { labels, lw, rows, cols, cw, ch };
    }

    draw() {
        if (!this.rows || !this.fit()) return;
        const g = this.g;
        const { labels, lw, rows, cols, cw, ch } = this.layout();
        const min = this.num(["min", "value_min"], 0), max = this.num(["max", "value_max"], 1);
        const table = colorTable(this.mapName(), this.str(["colorTable", "color_map_colors"]));
        const shape = this.str(["shape"], "rectangle");
        const size = this.num(["size"], 1);
        const stroke = this.str(["color", "stroke_color"]);
        const flipX = this.bool(["flipXCanvas", "flip_x_canvas"]), flipY = this.bool(["flipYCanvas", "flip_y_canvas"]);
        const level = (v) => Math.max(0, Math.min(255, Math.round(((v - min) / (max - min || 1)) * 255)));
        this.lineStyle(g);
        g.font = "11px sans-serif";
        g.textBaseline = "middle";
        for (let r = 0; r < rows; r++) {
            const rr = flipY ? rows - 1 - r : r;
            if (labels.length) { g.fillStyle = this.cssVar("--text-color", "#333"); g.fillText(labels[r % labels.length], 2, rr * ch + ch / 2); }
            for (let c = 0; c < cols; c++) {
                const cc = flipX ? cols - 1 - c : c;
                let color;
                if (this.channels) {
                    color = `rgb(${this.channels.map((ch_) => level(ch_[r][c])).join(",")})`;
                } else {
                    const [R, G, B] = table[level(this.rows[r][c])];
                    color = `rgb(${R},${G},${B})`;
                }
                g.fillStyle = color;
                const x = lw + cc * cw + (cw * (1 - size)) / 2, y = rr * ch + (ch * (1 - size)) / 2;
                const sw = cw * size, sh = ch * size;
                if (shape === "circle") {
                    g.beginPath();
                    g.ellipse(x + sw / 2, y + sh / 2, sw / 2, sh / 2, 0, 0, 2 * Math.PI);
                    g.fill();
                    if (stroke) { g.strokeStyle = stroke; g.stroke(); }
                } else {
                    g.fillRect(x, y, sw, sh);
                    if (stroke) { g.strokeStyle = stroke; g.strokeRect(x, y, sw, sh); }
                }
            }
        }
    }

    async click(e) {
        if (!this.rows) return;
        const { lw, rows, cols, cw, ch } = this.layout();
        const rect = this.canvas.getBoundingClientRect();
        const zoom = rect.width / (this.width || rect.width);      // a view fitted to its pane
        let c = Math.floor(((e.clientX - rect.left) / zoom - lw) / cw), r = Math.floor((e.clientY - rect.top) / zoom / ch);
        if (this.bool(["flipXCanvas", "flip_x_canvas"])) c = cols - 1 - c;
        if (this.bool(["flipYCanvas", "flip_y_canvas"])) r = rows - 1 - r;
        if (c < 0 || c >= cols || r < 0 || r >= rows) return;
        const on = this.num(["valueHigh", "on_value"], 1), off = this.num(["valueLow", "off_value"], 0);
        const command = this.commandTarget("command");
        if (command) await this.sendCommand(command, c, r, on);
        const param = this.path("parameter");
        if (param) {
            if (this.paramValue === null) this.paramValue = await this.readParameter(param);
            if (this.paramValue === null) return;
            const next = Widget.element(this.paramValue, c, r) === on ? off : on;
            // kept at once, so a second click before the answer toggles back
            this.paramValue = Widget.withElement(this.paramValue, c, r, next);
            const answer = await this.setParameter(param, next, c, r);
            if (answer) this.paramValue = answer.value;
        }
    }
}
