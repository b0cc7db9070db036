// The base of every widget: attributes (Ikaros 2 and Ikaros 3 spellings), the frame and
// title, path resolution, colours and colour maps, and a canvas helper.
//
// A widget class is constructed with (attrs, ctx) where attrs are the widget's attributes
// as strings (from /api/network) and ctx = {groupPath, api, selectModule, notify}. It
// builds this.el and answers:
//   subscriptions()  -> [{path, format}]   buffers it wants over the WebSocket
//   parameters()     -> [path]             parameters whose current values it shows
//   update(frame)    new data: frame.get(path, format) -> {shape, data} or undefined
//   setParameters(values)  values: Map(path -> current value)
//   destroy()

import { api, splitCommand } from "../api.js";

const TRUE = new Set(["yes", "true", "1", "on"]);

export function truthy(text) {
    return TRUE.has(String(text).trim().toLowerCase());
}

/** Resolve a path written relative to a group. */
export function resolvePath(groupPath, text) {
    if (text === undefined || text === null || text === "") return "";
    text = String(text).trim();
    if (text.startsWith(".")) return text.slice(1);        // already from the top
    return groupPath ? `${groupPath}.${text}` : text;
}

/** Rows and columns of a buffer shape (higher ranks are folded into rows). */
export function rowsCols(shape) {
    if (!shape || shape.length === 0) return [1, 1];
    if (shape.length === 1) return [1, shape[0]];
    const cols = shape[shape.length - 1];
    return [shape.slice(0, -1).reduce((a, b) => a * b, 1), cols];
}

/** A buffer as rows: an array of Float32Array rows. */
export function asRows(item) {
    const [rows, cols] = rowsCols(item.shape);
    const out = [];
    for (let r = 0; r < rows; r++) out.push(item.data.subarray(r * cols, (r + 1) * cols));
    return out;
}

/** A nested JSON value (parameter) as a flat array of numbers and the row length. */
export function flatten(value) {
    if (Array.isArray(value)) {
        if (value.length && Array.isArray(value[0])) return { flat: value.flat(Infinity), cols: value[0].length };
        return { flat: value, cols: value.length };
    }
    return { flat: [value], cols: 1 };
}

// --- colour maps ----------------------------------------------------------------------

function lerpTable(stops, n = 256) {
    const table = [];
    for (let i = 0; i < n; i++) {
        const t = (i / (n - 1)) * (stops.length - 1);
        const k = Math.min(Math.floor(t), stops.length - 2);
        const f = t - k;
        const a = stops[k], b = stops[k + 1];
        table.push([0, 1, 2].map((c) => Math.round(a[c] + (b[c] - a[c]) * f)));
    }
    return table;
}

export const COLOR_MAPS = {
    gray: lerpTable([[0, 0, 0], [255, 255, 255]]),
    fire: lerpTable([[0, 0, 0], [128, 0, 0], [230, 40, 0], [255, 160, 0], [255, 240, 80], [255, 255, 255]]),
    spectrum: lerpTable([[128, 0, 128], [0, 0, 255], [0, 200, 255], [0, 200, 0], [255, 255, 0], [255, 128, 0], [255, 0, 0]]),
    red: lerpTable([[0, 0, 0], [255, 0, 0]]),
    green: lerpTable([[0, 0, 0], [0, 255, 0]]),
    blue: lerpTable([[0, 0, 0], [0, 0, 255]]),
};

let probe = null;
/** Any CSS colour as [r, g, b, a 0..1]. */
export function parseColor(text) {
    if (!probe) { probe = document.createElement("canvas").getContext("2d"); }
    probe.fillStyle = "#000";
    probe.fillStyle = text;
    const c = probe.fillStyle;
    if (c.startsWith("#")) {
        return [parseInt(c.slice(1, 3), 16), parseInt(c.slice(3, 5), 16), parseInt(c.slice(5, 7), 16), 1];
    }
    const m = c.match(/[\d.]+/g) || [0, 0, 0, 1];
    return [+m[0], +m[1], +m[2], m[3] === undefined ? 1 : +m[3]];
}

/** A 256-entry colour table by name, or from a comma list of colours (custom). */
export function colorTable(name, custom) {
    if (name === "custom" && custom) {
        const stops = custom.split(",").map((c) => parseColor(c.trim()).slice(0, 3));
        if (stops.length === 1) stops.unshift([0, 0, 0]);
        return lerpTable(stops);
    }
    return COLOR_MAPS[name] || COLOR_MAPS.gray;
}

// --- the base class -------------------------------------------------------------------

export class Widget {
    /** Title shown when the widget has none. */
    static defaultTitle = "";

    constructor(attrs, ctx = {}) {
        this.attrs = attrs;
        this.ctx = ctx;
        this.groupPath = ctx.groupPath || "";
        this.el = document.createElement("div");
        this.el.className = "widget widget-" + (attrs.class || "unknown");
        this.el.dataset.widget = attrs.class || "";
        if (attrs.name) this.el.dataset.name = attrs.name;
        const title = this.str(["title"], this.str(["name"], this.constructor.defaultTitle));
        this.el.dataset.title = title;
        const showTitle = this.bool(["show_title"], title !== "");
        if (showTitle && title) {
            this.titleEl = document.createElement("div");
            this.titleEl.className = "widget-title";
            this.titleEl.textContent = title;
            this.el.appendChild(this.titleEl);
            const src = this.path("source");
            if (src && ctx.selectModule) {
                this.titleEl.title = "Show " + src;
                this.titleEl.addEventListener("click", () => ctx.selectModule(src.split(".").slice(0, -1).join(".")));
            }
        }
        this.body = document.createElement("div");
        this.body.className = "widget-body";
        this.el.appendChild(this.body);
        if (!this.bool(["show_frame", "frame"], true)) this.el.classList.add("no-frame");
        this.applyStyle();
    }

    /** The first attribute present among the spellings. */
    raw(names) {
        for (const n of names) {
            if (this.attrs[n] !== undefined && this.attrs[n] !== null && this.attrs[n] !== "") return this.attrs[n];
        }
        return undefined;
    }

    str(names, def = "") { const v = this.raw(names); return v === undefined ? def : String(v); }

    num(names, def = 0) {
        const v = this.raw(names);
        const x = v === undefined ? NaN : parseFloat(v);
        return Number.isFinite(x) ? x : def;
    }

    int(names, def = 0) { return Math.round(this.num(names, def)); }

    bool(names, def = false) { const v = this.raw(names); return v === undefined ? def : truthy(v); }

    list(names, def = []) {
        const v = this.raw(names);
        if (v === undefined) return def;
        return String(v).split(",").map((s) => s.trim());
    }

    /** A full path for a source/parameter attribute: the server's "<name>_path" or resolved. */
    path(name, ...alternatives) {
        for (const n of [name, ...alternatives]) {
            // the server's resolution wins; null there means the path does not resolve
            if (Object.prototype.hasOwnProperty.call(this.attrs, n + "_path")) return this.attrs[n + "_path"] || "";
            if (this.attrs[n]) return resolvePath(this.groupPath, this.attrs[n]);
        }
        return "";
    }

    /** The target of a command attribute: {module, name} (server's <attr>_module/_name, or
     *  split from the path written relative to the group), or null. */
    commandTarget(...names) {
        for (const n of names) {
            if (this.attrs[n + "_module"] !== undefined && this.attrs[n + "_name"]) {
                return { module: this.attrs[n + "_module"] || "", name: this.attrs[n + "_name"] };
            }
            if (this.attrs[n]) {
                const text = n === "command" && this.attrs.module ? `${this.attrs.module}.${this.attrs[n]}` : this.attrs[n];
                return splitCommand(resolvePath(this.groupPath, text));
            }
        }
        return null;
    }

    /** The colour list for series: the widget's attribute, else the theme's. */
    colors(names, cssVar = "--series-colors") {
        const own = this.list(names, null);
        if (own && own.length && own[0] !== "") return own;
        const theme = getComputedStyle(this.el).getPropertyValue(cssVar).trim();
        return theme ? theme.split(",").map((s) => s.trim()) : ["#2a7ab9"];
    }

    cssVar(name, def) {
        const v = getComputedStyle(this.el).getPropertyValue(name).trim();
        return v || def;
    }

    applyStyle() {
        const style = this.str(["style"]);
        if (style) this.body.style.cssText += ";" + style;
        const frameStyle = this.str(["frame-style", "frame_style"]);
        if (frameStyle) this.el.style.cssText += ";" + frameStyle;
        const bg = this.str(["background"]);
        if (bg) this.el.style.background = bg;
        const fc = this.str(["frame_color"]);
        if (fc) this.el.style.borderColor = fc;
        const fw = this.raw(["frame_width"]);
        if (fw !== undefined) this.el.style.borderWidth = parseFloat(fw) + "px";
    }

    subscriptions() { return []; }
    parameters() { return []; }
    update(frame) { }
    setParameters(values) { }
    resize() { }
    destroy() { }

    /** Send a command: target is {module, name} (commandTarget) or a full "Module.cmd". */
    async sendCommand(target, x = 0, y = 0, value = null) {
        if (!target) return;
        const { module, name } = typeof target === "string" ? splitCommand(target) : target;
        try {
            return await api.command(module, name, x, y, value);
        } catch (e) {
            this.ctx.notify?.("error", `command ${module}.${name}: ${e.message}`);
        }
    }

    /** The current value of a parameter "Module.name", read from the server. */
    async readParameter(path) {
        const i = path.lastIndexOf(".");
        try {
            const info = await api.module(path.slice(0, i));
            const p = (info.parameters || []).find((q) => q.name === path.slice(i + 1));
            return p ? p.value : null;
        } catch (e) {
            this.ctx.notify?.("error", `parameter ${path}: ${e.message}`);
            return null;
        }
    }

    async setParameter(path, value, x, y) {
        try {
            return await api.setParameter(path, value, x, y);
        } catch (e) {
            this.ctx.notify?.("error", `parameter ${path}: ${e.message}`);
        }
    }

    /** Element (x, y) of a parameter value, or the value itself when it is a scalar. */
    static element(value, x = 0, y = 0) {
        if (Array.isArray(value)) {
            if (Array.isArray(value[0])) return (value[y] || [])[x];
            return value[x];
        }
        return value;
    }

    /** A copy of a parameter value with element (x, y) set to v (v itself for a scalar). */
    static withElement(value, x, y, v) {
        if (!Array.isArray(value)) return v;
        if (Array.isArray(value[0])) return value.map((row, i) => (i === y ? row.map((e, j) => (j === x ? v : e)) : row));
        return value.map((e, j) => (j === x ? v : e));
    }

    /** The accessible name of a control: its own label, else the widget's title, else the
     *  first of the attributes (a parameter or command as written) that is given, else the
     *  class; with the element's index when the widget has several controls. */
    controlName(label, index = null, attrs = ["parameter", "command"]) {
        if (label) return label;
        const base = this.el.dataset.title || this.str(attrs) || this.attrs.class || "control";
        return index === null ? base : `${base} ${index}`;
    }

    /** Disable form controls while the enabled source says so (``enabled``, set from
     *  ``enabledFrom`` each frame) and, for a widget bound to a parameter, until the
     *  parameter's value has arrived: used before, a control would act on a value it does
     *  not know (a slider step from its minimum, a menu sending the wrong kind of value). */
    setControlsDisabled(controls) {
        const waiting = this.paramValue === null && this.parameters().length > 0;
        for (const c of controls) c.disabled = this.enabled === false || waiting;
    }

    /** Whether a widget's "enabled" source says it is disabled ([0][0] == 0). */
    enabledFrom(frame) {
        const p = this.path("enabled_source", "enableSource", "enable_source");
        if (!p) return true;
        const item = frame.get(p);
        return !item || item.data.length === 0 || item.data[0] !== 0;
    }

    enabledSubscription() {
        const p = this.path("enabled_source", "enableSource", "enable_source");
        return p ? [{ path: p, format: "raw" }] : [];
    }
}

/** A widget drawing on a canvas that fills its body (sized for the device pixel ratio). */
export class CanvasWidget extends Widget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        this.canvas = document.createElement("canvas");
        this.body.appendChild(this.canvas);
        this.g = this.canvas.getContext("2d");
        this.width = 0;
        this.height = 0;
    }

    /** Match the canvas to the body; returns false when it has no size yet. */
    fit() {
        const w = this.body.clientWidth, h = this.body.clientHeight;
        if (w === 0 || h === 0) return false;
        const dpr = window.devicePixelRatio || 1;
        if (w !== this.width || h !== this.height || this.canvas.width !== Math.round(w * dpr)) {
            this.width = w;
            this.height = h;
            this.canvas.width = Math.round(w * dpr);
            this.canvas.height = Math.round(h * dpr);
            this.canvas.style.width = w + "px";
            this.canvas.style.height = h + "px";
        }
        this.g.setTransform(dpr, 0, 0, dpr, 0, 0);
        this.g.clearRect(0, 0, w, h);
        return true;
    }

    lineStyle(g, i = 0) {
        g.lineWidth = this.num(["lineWidth", "line_width"], 1);
        g.lineCap = this.str(["lineCap", "line_cap"], "butt");
        g.lineJoin = this.str(["lineJoin", "line_join"], "miter");
    }

    /** Coordinate mapping for marker, path, grid and image (x_min.., flips). */
    coordinates() {
        const xmin = this.num(["x_min", "min_x"], 0), xmax = this.num(["x_max", "max_x"], 1);
        const ymin = this.num(["y_min", "min_y"], 0), ymax = this.num(["y_max", "max_y"], 1);
        const flipX = this.bool(["flip_x_axis", "flipXAxis", "flip_x_canvas", "flipXCanvas"], false);
        const flipY = this.bool(["flip_y_axis", "flipYAxis", "flip_y_canvas", "flipYCanvas"], false);
        const w = this.width, h = this.height;
        return {
            x: (v) => { const f = (v - xmin) / (xmax - xmin || 1); return (flipX ? 1 - f : f) * w; },
            y: (v) => { const f = (v - ymin) / (ymax - ymin || 1); return (flipY ? 1 - f : f) * h; },
        };
    }

    /** Value range: min/max (or y_min/y_max, value_min/value_max), widened by auto range. */
    range(values, defMin = 0, defMax = 1) {
        let min = this.num(["min", "y_min", "value_min"], defMin);
        let max = this.num(["max", "y_max", "value_max"], defMax);
        if (this.bool(["auto", "auto_range"], false) && values && values.length) {
            let lo = Infinity, hi = -Infinity;
            for (const v of values) { if (v < lo) lo = v; if (v > hi) hi = v; }
            if (this.bool(["include_zero"], true)) { lo = Math.min(lo, 0); hi = Math.max(hi, 0); }
            if (Number.isFinite(lo)) { min = lo; max = hi > lo ? hi : lo + 1; }
        }
        return [min, max];
    }
}

/** Format a number with a number of decimals (-1 or none: as it is). */
/** A canvas widget that draws one module: the ``module`` attribute names it, clicking the
 * title shows it in the inspector, and each buffer it reads is the ``<role>_source``
 * attribute ("none" hides that part), or else MODULE.OUTPUT. */
export class ModuleWidget extends CanvasWidget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        this.module = resolvePath(this.groupPath, this.str(["module"]));
        if (this.titleEl && this.module && ctx.selectModule && !this.titleEl.title) {
            this.titleEl.title = "Show " + this.module;
            this.titleEl.addEventListener("click", () => ctx.selectModule(this.module));
        }
    }

    buffer(role, output) {
        if (this.str([role + "_source"]).toLowerCase() === "none") return "";
        const own = this.path(role + "_source");
        if (own) return own;
        if (Object.prototype.hasOwnProperty.call(this.attrs, role + "_source_path")) return "";
        return this.module && output ? `${this.module}.${output}` : "";
    }
}

export function formatNumber(v, decimals) {
    if (typeof v !== "number") return String(v);
    if (decimals === undefined || decimals < 0) return String(Math.round(v * 1e6) / 1e6);
    return v.toFixed(decimals);
}
