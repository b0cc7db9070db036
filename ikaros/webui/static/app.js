// The browser app: loads the model, shows the navigator, views, run controls, inspectors and
// messages, and moves data from the WebSocket to the widgets.
import { api, Socket } from "./api.js";
import { Controls } from "./controls.js";
import { RecordButton, ReplayBar } from "./record.js";
import { SystemInspector } from "./inspector.js";
import { Messages } from "./messages.js";
import { ModuleInspector } from "./module-inspector.js";
import { Navigator } from "./navigator.js";
import { Panes } from "./panes.js";
import { ViewRenderer } from "./views.js";
import { Editor } from "./editor/editor.js";

const $ = (sel) => document.querySelector(sel);
const THEMES = ["light", "dark"];

/** A frame as widgets see it: get(path, format) -> {shape, data}. */
function frameView(frame) {
    return {
        tick: frame.tick,
        time: frame.time,
        buffers: frame.buffers,
        get(path, format = "raw") { return frame.buffers.get(path + "|" + format); },
    };
}

/** Shape of a nested list. */
function shapeOf(v) {
    const shape = [];
    while (Array.isArray(v)) { shape.push(v.length); v = v[0]; }
    return shape;
}

class App {
    constructor() {
        this.network = null;
        this.current = null;           // {group, view}
        this.built = null;             // the same once that view's widgets are all built
        this.mainView = null;
        this.shapes = new Map();
        this.socket = new Socket();
        this.status = {};
        this.frameTimes = [];
        this.lastFrame = null;
        this.params = new Map();
        this.messages = new Messages($("#messages"));
        this.system = new SystemInspector($("#system-inspector"), (l, m) => this.messages.local(l, m));
        this.controls = new Controls($("#controls"), {
            onStatus: (s) => this.showStatus(s),
            notify: (l, m) => this.messages.local(l, m),
            scope: () => (this.editor?.active ? this.editor.selectedComponentPath() : null),
        });
        this.recordButton = new RecordButton($("#controls"), { notify: (l, m) => this.messages.local(l, m),
            status: () => this.status });
        this.replayBar = new ReplayBar($("#controls"), { notify: (l, m) => this.messages.local(l, m), recordButton: this.recordButton });
        this.ctx = {
            groupPath: "",
            selectModule: (path) => this.moduleInspector.open(path),
            notify: (level, message) => this.messages.local(level, message),
            shapeOf: (path) => this.shapes.get(path) || null,
        };
        this.moduleInspector = new ModuleInspector($("#module-inspector"), {
            notify: this.ctx.notify, ctx: this.ctx, onViewChange: () => this.resubscribe(),
        });
        this.navigator = new Navigator($("#navigator"), {
            onView: (group, view) => this.editor?.active ? this.editor.openGroup(group, view) : this.showView(group, view),
            onModule: (path) => this.editor?.active ? this.editor.selectPath(path) : this.moduleInspector.open(path),
        });
        this.editor = new Editor(this);
        this.setupChrome();
        this.setupSocket();
        setInterval(() => this.pollParameters(), 500);
        setInterval(() => this.showStatus(), 1000);
    }

    setupChrome() {
        const theme = $("#theme");
        const saved = localStorage.getItem("ikaros-theme");
        this.setTheme(THEMES.includes(saved) ? saved : "light");
        theme.addEventListener("change", () => this.setTheme(theme.value));
        $("#toggle-nav").addEventListener("click", () => document.body.classList.toggle("hide-nav"));
        $("#toggle-system").addEventListener("click", () => document.body.classList.toggle("hide-system"));
        $("#toggle-messages").addEventListener("click", () => document.body.classList.toggle("hide-messages"));
        this.panes = new Panes();
        $("#clear-messages").addEventListener("click", () => this.messages.clear());
        window.addEventListener("hashchange", () => {
            const c = this.fromHash();
            if (c && (!this.current || c.group !== this.current.group || c.view !== this.current.view)) this.showView(c.group, c.view);
        });
        document.addEventListener("keydown", (e) => {
            // not while typing or in a dialog, where Escape means cancel
            if (e.key === "Escape" && !e.target.closest("input, textarea, select, .editor-dialog-back")) {
                document.body.classList.toggle("hide-system");
            }
        });
    }

    setTheme(name) {
        $("#theme-css").href = `/static/themes/${name}.css`;
        $("#theme").value = name;
        document.documentElement.dataset.theme = name;
        localStorage.setItem("ikaros-theme", name);
        // canvases take their colours from the theme: redraw when the sheet has loaded
        $("#theme-css").onload = () => this.redraw();
    }

    redraw() {
        for (const v of [this.mainView, this.moduleInspector.view]) {
            if (!v) continue;
            for (const w of v.widgets) { try { w.draw?.(); w.render?.(); } catch { } }
        }
    }

    setupSocket() {
        const s = this.socket;
        s.addEventListener("open", () => { $("#overlay").hidden = true; this.showStatus(); });
        s.addEventListener("close", () => { $("#overlay").hidden = false; $("#overlay").textContent = "Disconnected: reconnecting…"; this.showStatus(); });
        s.addEventListener("status", (e) => this.showStatus(e.detail));
        s.addEventListener("log", (e) => this.messages.add(e.detail.messages || []));
        s.addEventListener("network", () => this.loadNetwork());
        s.addEventListener("error", (e) => this.messages.local("error", "server: " + (e.detail?.error || "error")));
        s.addEventListener("pong", () => this.showStatus());
        s.addEventListener("frame", (e) => this.onFrame(e.detail));
    }

    async start() {
        try {
            const log = await api.log(0);
            this.messages.add(log.messages || []);
        } catch (e) { this.messages.local("warning", "log: " + e.message); }
        await this.loadNetwork();
        try { this.showStatus(await api.status()); } catch { }
        this.socket.connect();
    }

    async loadNetwork() {
        try {
            this.network = await api.network();
        } catch (e) {
            this.messages.local("error", "network: " + e.message);
            return;
        }
        this.shapes.clear();
        this.lastFrame = null;          // a frame of the previous network: its ticks do not count
        const walk = (g) => {
            for (const m of g.modules || []) {
                for (const o of m.outputs || []) this.shapes.set(`${m.path}.${o.name}`, o.shape);
                for (const i of m.inputs || []) this.shapes.set(`${m.path}.${i.name}`, i.shape);
            }
            (g.groups || []).forEach(walk);
        };
        walk(this.network.top);
        this.editor.showFileName(this.network.file);
        document.title = `ikaros – ${this.network.name || this.network.file || ""}`;
        const c = this.fromHash() || this.current || { group: "", view: 0 };
        await this.showView(c.group, c.view);
        // the model did not build: it is fixed in the editor
        if (this.network.build_error && !this.editor.active) await this.editor.setActive(true);
    }

    findGroup(path, g = this.network?.top) {
        if (!g) return null;
        if (g.path === path) return g;
        for (const sub of g.groups || []) {
            const found = this.findGroup(path, sub);
            if (found) return found;
        }
        return null;
    }

    fromHash() {
        const h = new URLSearchParams(location.hash.slice(1));
        if (!h.has("group")) return null;
        return { group: h.get("group"), view: parseInt(h.get("view") || "0", 10) || 0 };
    }

    /** The group's own default view when the server gave none: one plot per output. */
    defaultView(group) {
        const widgets = [];
        let i = 0;
        for (const m of group.modules || []) {
            for (const o of m.outputs || []) {
                widgets.push({ class: "plot", title: `${m.name}.${o.name}`, source: `${m.name}.${o.name}`,
                    source_path: `${m.path}.${o.name}`, x: String(20 + 220 * (i % 3)), y: String(20 + 220 * Math.floor(i / 3)), width: "200", height: "200" });
                i++;
            }
        }
        return { name: "default", widgets };
    }

    async showView(groupPath, index = 0) {
        const group = this.findGroup(groupPath) || this.network?.top;
        if (!group) return;
        const views = group.views && group.views.length ? group.views : [this.defaultView(group)];
        index = Math.min(Math.max(0, index), views.length - 1);
        const view = views[index];
        this.current = { group: group.path, view: index };
        this.built = null;
        const hash = `#group=${encodeURIComponent(group.path)}&view=${index}`;
        if (location.hash !== hash) history.replaceState(null, "", hash);
        if (this.mainView) this.mainView.destroy();
        $("#view-title").textContent = `${group.path || group.name}${view.name ? " / " + view.name : ""}`;
        const renderer = new ViewRenderer($("#view-host"), view, { ...this.ctx, groupPath: group.path });
        this.mainView = renderer;
        await renderer.build();
        if (this.mainView !== renderer) return;
        this.built = this.current;
        if (!this.editor?.active) this.navigator.show(this.network, this.current);
        this.resubscribe();
        this.pollParameters();
    }

    views() { return [this.mainView, this.moduleInspector.view, this.editor?.viewEditor].filter(Boolean); }

    resubscribe() {
        const seen = new Map();
        const subs = [];
        for (const v of this.views()) {
            for (const s of v.subscriptions()) {
                const key = s.path + "|" + s.format;
                if (!s.path) continue;
                if (seen.has(key)) {        // a history shared by plots: the widest one's points
                    const had = seen.get(key);  // and the longest one's ticks
                    if (s.points && had.points) had.points = Math.max(had.points, s.points);
                    if (s.ticks && had.ticks) had.ticks = Math.max(had.ticks, s.ticks);
                    else delete had.ticks;
                    continue;
                }
                const sub = { path: s.path, format: s.format || "raw" };
                if (s.points) sub.points = s.points;
                if (s.ticks) sub.ticks = s.ticks;
                seen.set(key, sub);
                subs.push(sub);
            }
        }
        this.socket.subscribe(subs);
        this.initialData(subs);
    }

    /** Current values at once (also while paused), through a one-off read. */
    async initialData(subs) {
        const paths = [...new Set(subs.map((s) => s.path))];
        if (!paths.length) return;
        let answer;
        try { answer = await api.data(paths); } catch {
            // one bad path must not hide the others: read them one by one
            answer = { tick: null, data: {} };
            await Promise.all(paths.map(async (p) => {
                try { const a = await api.data([p]); Object.assign(answer.data, a.data); answer.tick = a.tick; } catch { }
            }));
        }
        const buffers = new Map();
        for (const [path, value] of Object.entries(answer.data || {})) {
            const shape = shapeOf(value);
            const flat = Array.isArray(value) ? value.flat(Infinity) : [value];
            const item = { path, format: "raw", shape, data: Float32Array.from(flat.map(Number)) };
            buffers.set(path + "|raw", item);
            for (const s of subs) if (s.path === path && s.format !== "raw") buffers.set(path + "|" + s.format, null);
        }
        for (const [k, v] of [...buffers]) if (v === null) buffers.delete(k);
        let tick = answer.tick;
        const last = this.lastFrame;
        if (last && tick !== null && last.tick >= tick) {
            // a frame as new or newer came while this read was on its way: its values win
            // (the read's would undo it), the read fills in what the frame lacks
            for (const k of [...buffers.keys()]) if (last.buffers.has(k)) buffers.set(k, last.buffers.get(k));
            tick = last.tick;
        }
        const fv = frameView({ tick, time: null, buffers });
        for (const v of this.views()) v.update(fv);
    }

    onFrame(frame) {
        this.lastFrame = frame;
        const now = performance.now();
        this.frameTimes.push(now);
        while (this.frameTimes.length && this.frameTimes[0] < now - 2000) this.frameTimes.shift();
        const fv = frameView(frame);
        for (const v of this.views()) v.update(fv);
        requestAnimationFrame(() => this.socket.ready());
    }

    uiFigures() {
        const now = performance.now();
        const recent = this.frameTimes.filter((t) => t >= now - 2000);
        const s = this.status;
        let lagTicks = null, lagSeconds = 0;
        if (this.lastFrame && typeof s.tick === "number" && typeof this.lastFrame.tick === "number") {
            lagTicks = Math.max(0, s.tick - this.lastFrame.tick);
            // in wall-clock time: ticks behind at the kernel's present rate
            lagSeconds = s.ticks_per_second > 0 ? lagTicks / s.ticks_per_second : 0;
        }
        return { updatesPerSecond: recent.length / 2, rtt: this.socket.rtt, lagTicks, lagSeconds, connected: this.socket.connected };
    }

    showStatus(status) {
        if (status) {
            const { type, ...figures } = status;
            this.status = { ...this.status, ...figures };
        }
        this.controls.show(this.status);
        this.recordButton?.statusChanged();
        this.system.show(this.status, this.uiFigures());
        document.body.dataset.state = this.status.state || "";
    }

    /** Widgets that show parameter values get them twice a second. */
    async pollParameters() {
        const paths = new Set(this.views().flatMap((v) => v.parameters()));
        if (!paths.size) return;
        const modules = new Map();
        for (const p of paths) {
            const i = p.lastIndexOf(".");
            const m = p.slice(0, i);
            if (!modules.has(m)) modules.set(m, []);
            modules.get(m).push(p);
        }
        const values = new Map();
        const writes = api.parameterWrites;
        await Promise.all([...modules].map(async ([m, ps]) => {
            try {
                const info = await api.module(m);
                for (const prm of info.parameters || []) {
                    const full = `${m}.${prm.name}`;
                    if (ps.includes(full)) values.set(full, prm.value);
                }
            } catch { }
        }));
        // values read while a widget was writing may predate the write
        if (api.parameterWrites !== writes) return;
        this.params = values;
        for (const v of this.views()) v.setParameters(values);
    }
}

const app = new App();
window.ikaros = app;
app.start();
