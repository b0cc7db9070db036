// The network editor: a mode of the app (the "Edit" toggle in the toolbar). It edits its
// own copy of the model tree (GET /api/model) and sends the whole tree back to apply
// (rebuild and keep running) or to save (docs/webui-protocol.md, "The editor").
import { api } from "../api.js";
import { WIDGETS } from "../widgets/index.js";
import { pickClass } from "./class-list.js";
import { dialog } from "../dialog.js";
import { ask, files, pickFile } from "./files.js";
import { EditorInspector } from "./inspector.js";
import { BOX_W, ELK_LIMIT, HEADER, PORT_H, graphOf, layout, loadElk, storedPosition } from "./layout.js";
import { EditorModel, GROUP_WIDGETS, clone, elements, kids, node, setWidgetBox, treeAsNetwork, viewsOf, widgetBox } from "./model.js";
import { NetworkView } from "./network-view.js";
import { RouteKeeper } from "./routes.js";
import { ViewEditor } from "./view-editor.js";

function h(tag, cls, text) {
    const e = document.createElement(tag);
    if (cls) e.className = cls;
    if (text !== undefined) e.textContent = text;
    return e;
}

const isComponent = (n) => n && (n.tag === "module" || n.tag === "group");

// the room a new box keeps from the others: as the automatic layout leaves between layers
// (connections, their delay badges) and between boxes of a layer
const ROOM_X = 90, ROOM_Y = 40;
// places around the middle of the view, nearest first, for a new box (freeSpot)
const SPOT_OFFSETS = [];
for (let i = -40; i <= 40; i++) for (let j = -30; j <= 30; j++) SPOT_OFFSETS.push([i * 20, j * 20]);
SPOT_OFFSETS.sort((a, b) => Math.hypot(...a) - Math.hypot(...b));

export class Editor {
    /** app: the App (navigator, messages, network). */
    constructor(app) {
        this.app = app;
        this.model = new EditorModel();
        this.active = false;
        this.groupPath = "";
        this.mode = "network";          // or a view index
        this.selection = new Set();
        this.errors = new Map();        // node -> message
        this.groupError = null;
        this.classes = {};
        this.clipboard = null;
        this.transforms = new Map();    // group path -> zoom/pan
        this.graph = null;
        this.positions = new Map();
        this.automatic = false;
        this.renderSeq = 0;
        this.notify = (level, message) => app.messages.local(level, message);
        this.buildChrome();
        this.model.addEventListener("change", (e) => this.onModelChange(e.detail));
        this.classesLoaded = null;
        // the class list takes the server a second to gather: fetched while the page idles,
        // so that the editor opens at once
        setTimeout(() => this.loadClasses().then(() => loadElk()).catch(() => { }), 500);
    }

    loadClasses() {
        this.classesLoaded ||= api.classes().then((c) => { this.classes = c; }).catch((e) => {
            this.classesLoaded = null;
            this.notify("error", "classes: " + e.message);
        });
        return this.classesLoaded;
    }

    // --- chrome --------------------------------------------------------------------------

    buildChrome() {
        const toggle = h("button", "tool", "Edit");
        toggle.id = "toggle-editor";
        toggle.title = "edit the network and its views";
        toggle.addEventListener("click", () => this.setActive(!this.active));
        document.querySelector("#toolbar .spacer").before(toggle);
        this.toggleButton = toggle;

        this.area = h("div", "editor-area");
        this.area.id = "editor-area";
        this.area.hidden = true;
        const bar = h("div", "editor-bar");
        bar.id = "editor-bar";
        const button = (id, label, title, fn) => {
            const b = h("button", "tool small", label);
            b.id = id;
            b.title = title;
            b.addEventListener("click", fn);
            bar.appendChild(b);
            return b;
        };
        const sep = () => bar.appendChild(h("span", "editor-sep"));
        button("ed-new", "New", "a new empty model", () => this.newModel());
        button("ed-open", "Open…", "open another model from the folder", () => this.openModel());
        button("ed-save", "Save", "save to the model's file", () => this.save());
        button("ed-save-as", "Save as…", "save as a new .ikg file", () => this.save(true));
        sep();
        button("ed-apply", "Apply", "rebuild the network from the edited model (modules that did not change keep their state)", () => this.apply());
        sep();
        this.undoButton = button("ed-undo", "Undo", "undo (Ctrl-Z)", () => this.model.undo());
        this.redoButton = button("ed-redo", "Redo", "redo (Ctrl-Shift-Z)", () => this.model.redo());
        sep();
        this.netTools = [
            button("ed-add-module", "+ Module", "add a module", () => this.addModule()),
            button("ed-add-group", "+ Group", "add a group", () => this.addGroup()),
            button("ed-add-input", "+ Input", "add a group input", () => this.addPin("input")),
            button("ed-add-output", "+ Output", "add a group output", () => this.addPin("output")),
        ];
        this.widgetMenu = h("select", "tool small");
        this.widgetMenu.id = "ed-add-widget";
        this.widgetMenu.setAttribute("aria-label", "add a widget");
        this.widgetMenu.add(new Option("+ Widget", ""));
        for (const name of Object.keys(WIDGETS)) this.widgetMenu.add(new Option(name, name));
        this.widgetMenu.addEventListener("change", () => { const c = this.widgetMenu.value; this.widgetMenu.value = ""; if (c) this.addWidget(c); });
        bar.appendChild(this.widgetMenu);
        button("ed-delete", "Delete", "delete the selection (Del)", () => this.deleteSelection());
        button("ed-copy", "Copy", "copy (Ctrl-C)", () => this.copy());
        button("ed-paste", "Paste", "paste (Ctrl-V)", () => this.paste());
        button("ed-duplicate", "Duplicate", "duplicate (Ctrl-D)", () => this.duplicate());
        button("ed-cut", "Cut", "cut (Ctrl-X)", () => this.cut());
        button("ed-select-all", "Select all", "select every element (Ctrl-A)", () => this.selectAll());
        sep();
        this.layoutTools = [
            button("ed-align-left", "⇤ Align", "align the selected boxes on the left", () => this.align("x")),
            button("ed-align-top", "⤒ Align", "align the selected boxes at the top", () => this.align("y")),
            button("ed-auto-layout", "Auto layout", "lay out the group along the data flow", () => this.autoLayout()),
            button("ed-zoom-out", "−", "zoom out", () => this.netView?.zoom(1 / 1.25)),
            button("ed-zoom-in", "+", "zoom in", () => this.netView?.zoom(1.25)),
            button("ed-fit", "Fit", "fit the group into the view", () => this.netView?.fit()),
        ];
        const tabs = h("div", "editor-tabs");
        tabs.id = "editor-tabs";
        this.tabs = tabs;
        this.crumbs = h("div", "editor-crumbs");
        this.crumbs.id = "editor-crumbs";
        this.status = h("div", "editor-status");
        this.status.id = "editor-status";
        this.host = h("div", "editor-host");
        this.host.id = "editor-host";
        this.area.append(bar, this.crumbs, tabs, this.status, this.host);
        document.querySelector("#view-area").appendChild(this.area);

        const insp = h("section", "editor-inspector");
        insp.id = "editor-inspector";
        insp.hidden = true;
        document.querySelector("#inspector").prepend(insp);
        this.inspectorEl = insp;
        this.inspector = new EditorInspector(insp, {
            edit: (label, fn) => this.edit(label, fn),
            rename: (n, name) => this.rename(n, name),
            classes: () => this.classes,
            sources: () => this.sourcesInGroup(),
            parameters: () => this.parametersInGroup(),
            error: (n) => this.errors.get(n) || null,
            parentOf: (n) => { const c = this.model.chain(n); return c && c.length > 1 ? c[c.length - 2] : null; },
        });
        document.addEventListener("keydown", (e) => this.onKey(e));
        // edits that are not on disk: the browser asks before the tab closes or reloads
        window.addEventListener("beforeunload", (e) => {
            if (!this.model.unsaved) return;
            e.preventDefault();
            e.returnValue = "";
        });
    }

    async setActive(on) {
        this.active = on;
        document.body.classList.toggle("editing", on);
        this.toggleButton.classList.toggle("active", on);
        this.area.hidden = !on;
        this.inspectorEl.hidden = !on;
        document.querySelector("#view-host").hidden = on;
        document.querySelector("#view-title").hidden = on;
        if (on) {
            if (!Object.keys(this.classes).length) await this.loadClasses();
            if (!this.model.tree) await this.reload();
            else this.render();
        } else {
            this.app.navigator.show(this.app.network, this.app.current);
        }
    }

    async reload() {
        try {
            const m = await files.model();
            this.model.load(m);
            this.errors.clear();
            this.groupError = null;
            if (!this.model.group(this.groupPath)) this.groupPath = "";
            // the file did not build: its error on the element at fault
            if (m.error) this.showError({ message: m.error.error, body: m.error }, "Did not build", " Fix it here, then Apply.");
        } catch (e) {
            this.setStatus("error", "model: " + e.message);
        }
    }

    setStatus(level, text) {
        this.status.className = "editor-status level-" + level;
        this.status.textContent = text;
        this.status.dataset.level = level;
    }

    // --- edits -----------------------------------------------------------------------------

    group() { return this.model.group(this.groupPath) || this.model.tree; }

    edit(label, fn) {
        try {
            return this.model.do(label, fn);
        } catch (e) {
            this.notify("error", `${label}: ${e.message}`);
            this.setStatus("error", `${label}: ${e.message}`);
            this.render();
            return null;
        }
    }

    onModelChange(kind) {
        if (kind === "undo" || kind === "redo" || kind === "load") {
            this.selection.clear();
            if (!this.model.group(this.groupPath)) this.groupPath = "";
        }
        if (kind !== "load" && kind !== "edit") this.errors.clear();
        // forget the selection of nodes no longer in the tree
        for (const n of [...this.selection]) if (!this.model.chain(n)) this.selection.delete(n);
        this.updateTitle();
        if (this.active) this.rendering = this.render();
    }

    updateTitle() {
        this.undoButton.disabled = !this.model.canUndo();
        this.redoButton.disabled = !this.model.canRedo();
        this.showFileName(this.app.network?.file);
    }

    /** The file name in the toolbar, with "•" while edits are not saved (Apply does not
     *  save: the mark stays until Save). */
    showFileName(networkFile) {
        const el = document.querySelector("#file-name");
        if (!this.model.tree) { el.textContent = networkFile || ""; return; }
        const name = this.model.file || "(not saved)";
        el.textContent = name + (this.model.unsaved ? " •" : "");
        el.title = this.model.unsaved ? "edits not saved to the file" : "";
    }

    /** Write the present positions of every box of the group into _x/_y (inside an edit). */
    freeze(g) {
        if (!this.graph || g !== this.group()) return;
        for (const b of this.graph.boxes) {
            if (!isComponent(b.node) || b.readOnly) continue;
            const p = this.positions.get(b.key);
            if (p && !storedPosition(b)) { b.node.attrs._x = String(Math.round(p.x)); b.node.attrs._y = String(Math.round(p.y)); }
        }
    }

    /** A free place for a new box of w x hgt: the free place nearest to the middle of the
     *  view, clear of every box (those drawn, and those just added to the tree) by room for
     *  connections and their badges: ROOM_X beside it, ROOM_Y above and below. */
    freeSpot(w = BOX_W, hgt = 80) {
        const r = this.host.getBoundingClientRect();
        const t = this.netView?.t || { k: 1, x: 0, y: 0 };
        const cx = ((r.width || 800) / 2 - t.x) / t.k - w / 2, cy = ((r.height || 600) / 2 - t.y) / t.k - hgt / 2;
        const boxes = (this.graph?.boxes || []).map((b) => ({ ...this.positions.get(b.key), w: b.w, h: b.h })).filter((b) => b.x !== undefined);
        const drawn = new Set((this.graph?.boxes || []).map((b) => b.node));
        for (const { node: n } of elements(this.group())) {
            const p = (n.tag === "module" || n.tag === "group") && !drawn.has(n) && storedPosition({ node: n });
            if (p) boxes.push({ ...p, w: BOX_W, h: 80 });
        }
        const free = (x, y) => !boxes.some((b) => x < b.x + b.w + ROOM_X && b.x < x + w + ROOM_X &&
            y < b.y + b.h + ROOM_Y && b.y < y + hgt + ROOM_Y);
        // the view in the drawing's units: a place in it first, then the nearest elsewhere
        const vx0 = (20 - t.x) / t.k, vy0 = (20 - t.y) / t.k;
        const vx1 = ((r.width || 800) - 20 - t.x) / t.k, vy1 = ((r.height || 600) - 20 - t.y) / t.k;
        const inView = (x, y) => x >= vx0 && y >= vy0 && x + w <= vx1 && y + hgt <= vy1;
        for (const inside of [true, false]) {
            for (const [dx, dy] of SPOT_OFFSETS) {
                const x = Math.round((cx + dx) / 10) * 10, y = Math.round((cy + dy) / 10) * 10;
                if ((!inside || inView(x, y)) && free(x, y)) return { x, y };
            }
        }
        return { x: Math.round(cx / 10) * 10, y: Math.round((Math.max(cy, ...boxes.map((b) => b.y + b.h)) + 40) / 10) * 10 };
    }

    /** The height of a box of a class (its rows of ports). */
    boxHeight(cls) {
        const d = this.classes?.[cls];
        return HEADER + Math.max(d?.inputs?.length || 0, d?.outputs?.length || 0, 1) * PORT_H + 6;
    }

    async addModule() {
        if (this.mode !== "network") this.openMode("network");
        const cls = await pickClass(this.classes);
        if (!cls) return;
        const g = this.group();
        const h = this.boxHeight(cls);
        const at = this.freeSpot(BOX_W, h);
        const added = this.edit(`add ${cls}`, () => {
            this.freeze(g);
            const m = node("module", { class: cls, name: this.model.uniqueName(g, cls), _x: String(at.x), _y: String(at.y) });
            return EditorModel.insert(g, m);
        });
        if (added) {
            this.select([added]);
            this.netView?.reveal(at.x, at.y, BOX_W, h);     // no free place in the view: pan to it
        }
    }

    addGroup() {
        const g = this.group();
        const at = this.freeSpot();
        const added = this.edit("add group", () => {
            this.freeze(g);
            return EditorModel.insert(g, node("group", { name: this.model.uniqueName(g, "Group"), _x: String(at.x), _y: String(at.y) }));
        });
        if (added) this.select([added]);
    }

    async addPin(tag) {
        const g = this.group();
        const taken = new Set(kids(g, tag).map((n) => n.attrs.name));
        const name = await ask(`Add a group ${tag}`, "Name", tag === "input" ? "INPUT" : "OUTPUT");
        if (!name) return;
        if (taken.has(name)) { this.setStatus("error", `the group has an ${tag} "${name}" already`); return; }
        const added = this.edit(`add ${tag}`, () => { this.freeze(g); return EditorModel.insert(g, node(tag, { name })); });
        if (added) this.select([added]);
    }

    onConnect(from, to) {
        const addr = (end) => (end.box.kind === "module" || end.box.kind === "group") ? `${end.box.name}.${end.port}` : end.box.name;
        const g = this.group();
        const source = addr(from), target = addr(to);
        if (kids(g, "connection").some((c) => c.attrs.source === source && c.attrs.target === target)) return;
        const added = this.edit("connect", () => {
            this.freeze(g);
            return EditorModel.insert(g, node("connection", { source, target, delay: "1" }));
        });
        if (added) this.select([added]);
    }

    onMove(moves) {
        const g = this.group();
        this.edit("move", () => {
            this.freeze(g);
            for (const [key, p] of moves) {
                const b = this.graph.boxes.find((x) => x.key === key);
                if (b && isComponent(b.node)) { b.node.attrs._x = String(Math.round(p.x)); b.node.attrs._y = String(Math.round(p.y)); }
            }
        });
    }

    align(axis) {
        const sel = this.graph?.boxes.filter((b) => this.selection.has(b.node) && isComponent(b.node)) || [];
        if (sel.length < 2) { this.setStatus("info", "select two or more boxes to align them (shift-click)"); return; }
        const v = Math.min(...sel.map((b) => this.positions.get(b.key)[axis]));
        this.edit("align", () => {
            this.freeze(this.group());
            for (const b of sel) b.node.attrs["_" + axis] = String(Math.round(v));
        });
    }

    /** The network view's width / height, the shape an automatic layout aims at. */
    viewAspect() {
        const r = this.host?.getBoundingClientRect();
        return r && r.width > 0 && r.height > 0 ? r.width / r.height : 1.6;
    }

    async autoLayout() {
        if (!this.graph) return;
        const quick = await layout(this.graph, { force: true, aspect: this.viewAspect() });
        const { positions, routes } = (quick.later && await quick.later) || quick;   // a big group: elkjs's
        this.keepRoutes(this.graph, routes, positions);
        this.edit("auto layout", () => {
            for (const b of this.graph.boxes) {
                const p = positions.get(b.key);
                if (p && isComponent(b.node) && !b.readOnly) { b.node.attrs._x = String(p.x); b.node.attrs._y = String(p.y); }
            }
        });
        await this.rendering;           // drawn at the new positions: fit those, not the old
        this.netView?.fit();
    }

    /** Rename a module, a group (the top one too) or a group's input or output, with every
     *  address that reaches it. */
    rename(n, name) {
        const g = this.parentOf(n);
        if ((!g && n !== this.model.tree) || this.isReadOnly(n)) return;
        if (name === n.attrs.name) return;
        const pin = n.tag === "input" || n.tag === "output";
        const taken = !g ? false : pin ? kids(g, n.tag).some((p) => p !== n && p.attrs.name === name)
            : this.model.names(g).has(name);
        if (taken) { this.setStatus("error", `"${name}" is taken in this group`); this.render(); return; }
        const open = this.group();
        this.edit("rename", () => {
            this.freeze(open);
            if (pin) EditorModel.renamePort(this.model.tree, g, n, name);
            else EditorModel.rename(this.model.tree, n, name);
            // the open group, or one around it, may be the one renamed
            this.groupPath = this.model.chain(open).slice(1).filter((c) => c.tag === "group")
                .map((c) => c.attrs.name).join(".");
        });
    }

    parentOf(n) {
        const chain = this.model.chain(n);
        if (!chain) return null;
        // an include's elements belong to the element holding the include
        for (let i = chain.length - 2; i >= 0; i--) if (chain[i].tag !== "#include") return chain[i];
        return null;
    }

    deleteSelection() {
        const nodes = [...this.selection].filter((n) => !this.isReadOnly(n));
        if (!nodes.length) return;
        this.edit("delete", () => {
            this.freeze(this.group());
            for (const n of nodes) {
                const parent = this.parentOf(n);
                if (!parent) continue;
                if (isComponent(n)) EditorModel.deleteComponents(this.model.tree, parent, [n]);
                else EditorModel.remove(this.model.chain(n).at(-2), n);
            }
        });
        this.selection.clear();
        this.render();
    }

    isReadOnly(n) {
        const chain = this.model.chain(n);
        return !chain || chain.some((x) => x.tag === "#include");
    }

    copy() {
        const sel = [...this.selection];
        if (this.mode === "network") {
            const comps = sel.filter(isComponent);
            if (comps.length) this.clipboard = { kind: "network", ...EditorModel.copy(this.group(), comps) };
        } else {
            const ws = sel.filter((n) => !isComponent(n) && n.tag !== "connection");
            if (ws.length) this.clipboard = { kind: "view", nodes: ws.map((w) => clone(w)) };
        }
        if (this.clipboard) this.setStatus("info", `copied ${this.clipboard.nodes.length}`);
    }

    paste() {
        const clip = this.clipboard;
        if (!clip) return;
        if (clip.kind === "network" && this.mode === "network") {
            const g = this.group();
            const added = this.edit("paste", () => { this.freeze(g); return this.model.pasteInto(g, clip); });
            if (added) this.select(added);
        } else if (clip.kind === "view" && this.mode !== "network") {
            const v = this.currentView();
            if (!v) return;
            const added = this.edit("paste widgets", () => clip.nodes.map((w) => {
                const m = clone(w);
                const b = widgetBox(m);
                setWidgetBox(m, { x: b.x + 20, y: b.y + 20 });
                return this.addToView(v, m);
            }));
            if (added) this.select(added);
        }
    }

    duplicate() { this.copy(); this.paste(); }

    /** Copy the selection, then delete it (read-only elements stay). */
    cut() {
        this.copy();
        if (this.clipboard) this.deleteSelection();
    }

    /** elkjs's layout of a big group, from a Web Worker, in place of the quick one, unless
     *  the group was edited or left meanwhile; fitted to the view again if it was fitted
     *  (at transform ``fit``) and not panned or zoomed since. */
    async layoutArrives(later, seq, fit) {
        const result = await later;
        if (seq !== this.renderSeq || this.mode !== "network" || !this.netView) return;
        if (result) {
            this.keepRoutes(this.graph, result.routes, result.positions);
            this.positions = result.positions;
        }
        this.host.dataset.layout = "automatic";
        this.redraw();
        const t = this.netView.t;
        if (result && fit && t.k === fit.k && t.x === fit.x && t.y === fit.y) this.netView.fit();
    }

    /** Keep the routes of an automatic layout of the open group. */
    keepRoutes(graph, routes, positions) {
        if (routes) this.routesOfGroup().keepLayout(graph, routes, positions);
    }

    /** What keeps the routes of the open group's connections (routes.js). */
    routesOfGroup() {
        if (this.routing?.group !== this.groupPath) this.routing = new RouteKeeper(this.groupPath);
        return this.routing;
    }

    /** The routes of the open group's connections as drawn now; in a group of more than
     *  ELK_LIMIT boxes only those near the view at once, the others while the page idles. */
    currentRoutes() {
        if (!this.graph) return new Map();
        const near = this.graph.boxes.length > ELK_LIMIT && this.netView ? this.netView.visible(1) : null;
        const routes = this.routesOfGroup().routesFor(this.graph, this.positions, near);
        if (this.routing.pending.length) this.routeWhileIdle();
        return routes;
    }

    /** Route the pending connections in slices of idle time, those in the drawn part of the
     *  view first; draw again once those are routed, and when all are. */
    routeWhileIdle() {
        if (this.idleRouting) return;
        const idle = (f) => window.requestIdleCallback ? requestIdleCallback(f, { timeout: 300 })
            : setTimeout(() => f({ timeRemaining: () => 10, didTimeout: false }), 0);
        const step = (deadline) => {
            this.idleRouting = null;
            const keeper = this.routing, view = this.netView;
            if (!keeper?.pending.length || !view || this.mode !== "network") return;
            const t0 = performance.now();
            // a slice: the idle time left, or a few milliseconds when the page never idles
            const more = () => deadline.timeRemaining() > 2 || (deadline.didTimeout && performance.now() - t0 < 8);
            const { inArea, leftInArea, left } = keeper.routeSome(more, view.drawn || view.visible(1));
            if (view.routes === keeper.current && ((inArea && !leftInArea) || (!left && !view.drawn))) view.draw();
            if (left) this.idleRouting = idle(step);
        };
        this.idleRouting = idle(step);
    }

    /** The keys of the subgroups of a group whose unused ports are shown. */
    expandedPorts(groupPath) {
        this.portsShown ||= new Map();
        if (!this.portsShown.has(groupPath)) this.portsShown.set(groupPath, new Set());
        return this.portsShown.get(groupPath);
    }

    /** Show or hide a subgroup's unused ports (a view setting: the model is not changed). */
    togglePorts(key) {
        const set = this.expandedPorts(this.groupPath);
        if (set.has(key)) set.delete(key); else set.add(key);
        this.render();
    }

    /** Select the boxes a rubber band touched (added to the selection when additive). */
    band(keys, additive) {
        if (!additive) this.selection.clear();
        for (const k of keys) {
            const n = this.graph.boxes.find((b) => b.key === k)?.node;
            if (n && n !== this.group()) this.selection.add(n);
        }
        this.redraw();
    }

    /** Every box and connection of the open group, or every widget of the open view. */
    selectAll() {
        if (this.mode === "network") {
            const nodes = (this.graph?.boxes || []).filter((b) => b.node && b.node !== this.group()).map((b) => b.node)
                .concat((this.graph?.edges || []).map((e) => e.node).filter(Boolean));
            this.select([...new Set(nodes)]);
        } else {
            const v = this.currentView();
            this.select(v ? kids(v) : []);
        }
    }

    // --- views -----------------------------------------------------------------------------

    currentView() {
        if (this.mode === "network") return null;
        return viewsOf(this.group())[this.mode] || null;
    }

    /** Put widget w in view v (for the group's own widgets: a <widget> in the group). */
    addToView(v, w) {
        if (v.tag !== GROUP_WIDGETS) { v.children.push(w); return w; }
        if (w.tag !== "widget") w = node("widget", { class: w.tag, ...w.attrs }, w.children);
        return EditorModel.insert(v.group, w);
    }

    async addView() {
        const g = this.group();
        const name = await ask("Add a view", "Name", "View");
        if (name === null) return;
        const added = this.edit("add view", () => EditorModel.insert(g, node("view", { name })));
        if (added) this.openMode(viewsOf(g).indexOf(added));
    }

    deleteView() {
        const v = this.currentView();
        if (!v) return;
        const g = this.group();
        this.edit("delete view", () => {
            if (v.tag === GROUP_WIDGETS) for (const w of kids(v)) EditorModel.remove(g, w);
            else EditorModel.remove(g, v);
        });
        this.openMode("network");
    }

    addWidget(cls) {
        let v = this.currentView();
        const g = this.group();
        if (!v) {
            const views = viewsOf(g);
            v = views[0] || this.edit("add view", () => EditorModel.insert(g, node("view", { name: "View" })));
            this.mode = viewsOf(g).indexOf(v);
        }
        const n = kids(v).length;
        const added = this.edit(`add ${cls}`, () => {
            const w = node(cls, { title: cls, x: String(20 + 220 * (n % 3)), y: String(20 + 220 * Math.floor(n / 3)), width: "200", height: "200" });
            return this.addToView(v, w);
        });
        if (added) this.select([added]);
    }

    onGeometry(w, box) {
        if (this.isReadOnly(w)) { this.render(); return; }     // snaps back
        this.edit("move widget", () => setWidgetBox(w, box));
    }

    /** Every output a widget here can show: this group's modules' and its subgroups'
     *  outputs (paths from this group), then every other module output of the model (a
     *  leading "." starts at the top group). */
    sourcesInGroup() {
        const out = [], elsewhere = [], here = this.groupPath;
        for (const s of kids(this.group(), "group")) for (const o of kids(s, "output")) out.push(`${s.attrs.name}.${o.attrs.name}`);
        const walk = (g, path) => {
            for (const m of kids(g, "module")) {
                for (const o of this.classes[m.attrs.class]?.outputs || []) {
                    const full = [path, m.attrs.name, o.name].filter(Boolean).join(".");
                    if (!here) out.push(full);
                    else if (full.startsWith(here + ".")) out.push(full.slice(here.length + 1));
                    else elsewhere.push("." + full);
                }
            }
            for (const s of kids(g, "group")) walk(s, [path, s.attrs.name].filter(Boolean).join("."));
        };
        walk(this.model.tree, "");
        return [...out, ...elsewhere];
    }

    parametersInGroup() {
        const out = [];
        for (const m of kids(this.group(), "module")) for (const p of this.classes[m.attrs.class]?.parameters || []) out.push(`${m.attrs.name}.${p.name}`);
        return out;
    }

    // --- navigation and drawing --------------------------------------------------------------

    openGroup(path, view = null) {
        if (!this.model.group(path)) return;
        if (this.netView) this.transforms.set(this.groupPath, this.netView.t);
        this.groupPath = path;
        this.mode = view === null || view === undefined || view < 0 ? "network" : view;
        this.selection.clear();
        this.render();
    }

    /** The dotted path of the one module or group selected, or null (the scope of the
     *  state menu's save, load and reset). */
    selectedComponentPath() {
        if (this.selection.size !== 1) return null;
        const [n] = this.selection;
        if (!isComponent(n)) return null;
        const path = [this.groupPath, n.attrs.name].filter(Boolean).join(".");
        return path || null;
    }

    /** Open the group of a module (dotted path) and select the module. */
    selectPath(path) {
        const i = path.lastIndexOf(".");
        const group = i < 0 ? "" : path.slice(0, i), name = path.slice(i + 1);
        const g = this.model.group(group);
        const m = g && kids(g).find((c) => c.attrs.name === name);
        if (!m) return;
        if (group !== this.groupPath || this.mode !== "network") this.openGroup(group);
        this.select([m]);
    }

    openMode(mode) {
        this.mode = mode;
        this.selection.clear();
        this.render();
    }

    select(nodes, additive = false) {
        if (!additive) this.selection.clear();
        for (const n of nodes) {
            if (additive && this.selection.has(n)) this.selection.delete(n); else this.selection.add(n);
        }
        this.redraw();
    }

    /** Redraw with the present positions (no new layout). */
    redraw() {
        if (!this.active) return;
        if (this.mode === "network" && this.netView && this.graph) {
            this.netView.show(this.graph, this.positions, { errors: this.visibleErrors(), selection: this.selection, groupError: this.groupError, routes: this.currentRoutes() });
        } else if (this.viewEditor && this.currentView()) {
            this.viewEditor.show(this.currentView(), this.selection, this.errors);
        }
        this.showInspector();
    }

    /** Errors of nodes below the group's children are shown at the child. */
    visibleErrors() {
        const g = this.group();
        const out = new Map(this.errors);
        for (const [n, msg] of this.errors) {
            const chain = this.model.chain(n) || [];
            const i = chain.indexOf(g);
            if (i >= 0 && chain.length > i + 2) {
                let c = chain[i + 1];
                if (c.tag === "#include") c = chain[i + 2];
                if (!out.has(c)) out.set(c, msg);
            }
        }
        return out;
    }

    showInspector() {
        const sel = [...this.selection];
        this.inspector.show(sel, { group: this.group(), readOnly: sel.length === 1 && this.isReadOnly(sel[0]) });
    }

    async render() {
        if (!this.active || !this.model.tree) return;
        const seq = ++this.renderSeq;
        const g = this.group();
        this.updateTitle();
        this.app.navigator.show(treeAsNetwork(this.model.tree), { group: this.groupPath, view: this.mode === "network" ? -1 : this.mode });
        // breadcrumbs
        this.crumbs.textContent = "";
        const parts = this.groupPath ? this.groupPath.split(".") : [];
        const top = h("a", "crumb", this.model.tree.attrs.name || "(top)");
        top.href = "#";
        top.dataset.group = "";
        top.addEventListener("click", (e) => { e.preventDefault(); this.openGroup(""); });
        this.crumbs.appendChild(top);
        parts.forEach((p, i) => {
            this.crumbs.append(" ▸ ");
            const a = h("a", "crumb", p);
            a.href = "#";
            a.dataset.group = parts.slice(0, i + 1).join(".");
            a.addEventListener("click", (e) => { e.preventDefault(); this.openGroup(a.dataset.group); });
            this.crumbs.appendChild(a);
        });
        // tabs: the network and the views
        this.tabs.textContent = "";
        const tab = (label, mode, cls = "") => {
            const b = h("button", "editor-tab " + cls + (this.mode === mode ? " current" : ""), label);
            b.dataset.mode = String(mode);
            b.addEventListener("click", () => this.openMode(mode));
            this.tabs.appendChild(b);
            return b;
        };
        tab("Network", "network");
        viewsOf(g).forEach((v, i) => tab("▭ " + (v.attrs.name || `View #${i}`), i, "view-tab"));
        const addView = h("button", "editor-tab add-view", "+ View");
        addView.id = "ed-add-view";
        addView.addEventListener("click", () => this.addView());
        this.tabs.appendChild(addView);
        if (this.mode !== "network") {
            const del = h("button", "editor-tab", "Delete view");
            del.id = "ed-delete-view";
            del.addEventListener("click", () => this.deleteView());
            this.tabs.appendChild(del);
        }
        const network = this.mode === "network";
        for (const b of this.netTools.concat(this.layoutTools)) b.hidden = !network;
        if (network) {
            if (this.viewEditor) { this.viewEditor.destroy(); this.viewEditor = null; }
            if (!this.netView) {
                this.netView = new NetworkView(this.host, {
                    onSelect: (nodes, additive) => this.select(nodes, additive),
                    onOpenGroup: (name) => this.openGroup(this.groupPath ? `${this.groupPath}.${name}` : name),
                    onMove: (moves) => this.onMove(moves),
                    onConnect: (from, to) => this.onConnect(from, to),
                    onBand: (keys, additive) => this.band(keys, additive),
                    onTogglePorts: (key) => this.togglePorts(key),
                    routes: () => this.currentRoutes(),
                });
                this.netView.shownGroup = null;
            }
            const graph = graphOf(g, this.classes, this.expandedPorts(this.groupPath));
            const { positions, automatic, routes, later } = await layout(graph, { aspect: this.viewAspect() });
            if (seq !== this.renderSeq) return;
            this.keepRoutes(graph, routes, positions);
            this.graph = graph;
            this.positions = positions;
            this.automatic = automatic;
            this.host.dataset.layout = later ? "quick" : automatic ? "automatic" : "stored";
            this.redraw();
            const fitted = this.netView.shownGroup !== this.groupPath && !this.transforms.get(this.groupPath);
            if (this.netView.shownGroup !== this.groupPath) {
                this.netView.shownGroup = this.groupPath;
                const t = this.transforms.get(this.groupPath);
                if (t) this.netView.setTransform(t); else this.netView.fit();
            }
            this.host.dataset.ready = String(seq);
            if (later) this.layoutArrives(later, seq, fitted ? { ...this.netView.t } : null);
        } else {
            if (this.netView) { this.transforms.set(this.groupPath, this.netView.t); this.netView.destroy(); this.netView = null; }
            if (!this.viewEditor) {
                this.viewEditor = new ViewEditor(this.host, {
                    onSelect: (nodes, additive) => this.select(nodes, additive),
                    onGeometry: (w, box) => this.onGeometry(w, box),
                    live: () => ({ ctx: { ...this.app.ctx, groupPath: this.groupPath }, changed: () => this.app.resubscribe() }),
                });
            }
            if (!this.currentView()) { this.mode = "network"; this.render(); return; }
            this.redraw();
            this.host.dataset.ready = String(seq);
        }
    }

    // --- apply, files ------------------------------------------------------------------------

    async apply() {
        this.setStatus("info", "applying…");
        try {
            await files.apply(this.model.tree);
            this.errors.clear();
            this.groupError = null;
            this.model.dirty = false;
            this.setStatus("ok", "Applied: the network was rebuilt and goes on from its tick; modules that did not change kept their state.");
            this.notify("info", "the edited network was applied: rebuilt, unchanged modules kept their state");
            this.redraw();
            return true;
        } catch (e) {
            this.showError(e);
            return false;
        }
    }

    /** A 422 from apply or open (or the file that did not build): the error next to the
     *  element at fault. */
    showError(e, what = "Not applied", then = " The previous network keeps running.") {
        this.errors.clear();
        this.groupError = null;
        const body = e.body || {};
        let n = body.path ? this.model.atIndices(body.path) : null;
        if (!n && body.node !== null && body.node !== undefined) n = this.model.byId(body.node);
        // the kernel names the file with its folder: the file name is enough here
        const message = String(e.message).replace(/^[^\s:]*[\\/]([^\\/\s:]+\.ikg):/, "$1:");
        if (n && n !== this.model.tree) {
            this.errors.set(n, message);
            // open the group that holds the element
            const chain = this.model.chain(n) || [];
            const groups = chain.filter((x) => x.tag === "group" && x !== n);
            const path = groups.slice(1).map((x) => x.attrs.name).join(".");
            if (path !== this.groupPath && this.model.group(path) === groups.at(-1)) { this.groupPath = path; this.mode = "network"; }
            const view = chain.find((x) => x.tag === "view");
            const views = viewsOf(this.model.group(path));
            if (view) this.mode = views.indexOf(view);
            else if (n.tag === "widget") this.mode = views.findIndex((v) => v.tag === GROUP_WIDGETS);
        } else {
            this.groupError = message;
        }
        this.setStatus("error", `${what}: ` + message.replace(/\.?$/, ".") + then);
        this.notify("error", message);
        this.render();
    }

    async save(as = false) {
        let filename = null;
        if (as || !this.model.file) {
            filename = await ask("Save as", "File name", this.model.file || (this.model.tree.attrs.name || "model") + ".ikg", "save-as-name");
            if (!filename) return;
            if (!filename.endsWith(".ikg")) filename += ".ikg";
            if (filename !== this.model.file && !(await this.mayReplace(filename))) return;
        }
        await this.write(filename, filename && filename !== this.model.file ? undefined : this.model.version);
    }

    /** Save to filename (null: the model's file), checked against version (undefined:
     *  not checked); a save over another editor's is refused (409): reload or overwrite. */
    async write(filename, version) {
        try {
            const a = await files.save(this.model.tree, filename, version);
            this.model.file = a.file || filename || this.model.file;
            this.model.version = a.version ?? null;
            this.model.unsaved = false;
            this.updateTitle();
            this.setStatus("ok", `Saved ${this.model.file}.`);
        } catch (e) {
            if (e.status === 409 && "version" in (e.body || {})) return this.conflict(filename, e);
            this.setStatus("error", "Not saved: " + e.message);
        }
    }

    /** Another editor saved the file since these edits began: say so, and reload it (the
     *  edits here are lost) or overwrite it (the other editor's are). */
    conflict(filename, e) {
        this.setStatus("error", "Not saved: " + e.message + ".");
        const body = document.createElement("p");
        body.className = "dialog-note";
        body.textContent = e.message + ". Reload it (your edits here are lost) or overwrite it (the other edits are)?";
        const d = dialog("The file was changed", body, [
            ["Cancel", () => d.close(), "conflict-cancel"],
            ["Reload", async () => { d.close(); await this.reload(); this.setStatus("ok", "Reloaded the saved file."); }, "conflict-reload"],
            ["Overwrite", () => { d.close(); this.write(filename, e.body.version); }, "conflict-overwrite"],
        ]);
    }

    /** Whether a save-as may write filename: it is new, or the user agrees to replace it. */
    async mayReplace(filename) {
        let existing = [];
        try { existing = (await files.list()).files || []; } catch { }
        return !existing.includes(filename) || confirm(`${filename} exists. Replace it?`);
    }

    async newModel() {
        if (this.model.unsaved && !confirm("Discard the unsaved edits?")) return;
        const name = await ask("New model", "Name of the top group", "Untitled", "new-name");
        if (!name) return;
        try {
            await files.newModel(name);
            this.groupPath = "";
            this.mode = "network";
            await this.reload();
            this.setStatus("ok", `New model "${name}" (not saved yet).`);
        } catch (e) { this.setStatus("error", "New: " + e.message); }
    }

    async openModel() {
        if (this.model.unsaved && !confirm("Discard the unsaved edits?")) return;
        const f = await pickFile(this.notify);
        if (!f) return;
        try {
            await files.open(f);
            this.groupPath = "";
            this.mode = "network";
            await this.reload();
            this.setStatus("ok", `Opened ${f}.`);
        } catch (e) {
            this.setStatus("error", `${f} was not opened: ${e.message}`);
        }
    }

    onKey(e) {
        if (!this.active) return;
        const t = e.target;
        if (t && (t.tagName === "INPUT" || t.tagName === "TEXTAREA" || t.tagName === "SELECT" || t.isContentEditable)) return;
        if (document.querySelector(".editor-dialog-back")) return;
        const mod = e.ctrlKey || e.metaKey;
        const k = e.key.toLowerCase();
        if (mod && k === "z" && !e.shiftKey) this.model.undo();
        else if (mod && (k === "y" || (k === "z" && e.shiftKey))) this.model.redo();
        else if (mod && k === "c") this.copy();
        else if (mod && k === "v") this.paste();
        else if (mod && k === "d") this.duplicate();
        else if (mod && k === "x") this.cut();
        else if (mod && k === "a") this.selectAll();
        else if (mod && k === "s") this.save();
        else if (!mod && (e.key === "Delete" || e.key === "Backspace")) this.deleteSelection();
        else return;
        e.preventDefault();
    }
}
