// The editor's copy of the model tree (GET /api/model), the edit operations on it, and undo
// and redo. Every edit is a command run through do(label, fn): the tree before it is kept,
// so undo and redo restore whole trees (small: a model file's worth of JSON).
//
// A node is {id?, tag, attrs, text, children, file?, line?} (docs/webui-protocol.md, "The
// editor"). Elements inside an <?include?> ("#include" nodes) are shown but read-only.

export const INCLUDE = "#include";
export const COMMENT = "#comment";
const NAME = /^[A-Za-z_][A-Za-z0-9_-]*$/;

export function clone(x) { return JSON.parse(JSON.stringify(x)); }

export function node(tag, attrs = {}, children = []) {
    return { tag, attrs: { ...attrs }, text: null, children };
}

/** Child elements of a node, with included ones spliced in (each marked {node, readOnly}). */
export function elements(n, tag = null, readOnly = false) {
    const out = [];
    for (const c of n.children || []) {
        if (c.tag === INCLUDE) out.push(...elements(c, tag, true));
        else if (c.tag !== COMMENT && (tag === null || c.tag === tag)) out.push({ node: c, readOnly });
    }
    return out;
}

export function kids(n, tag) { return elements(n, tag).map((e) => e.node); }

/** Stands for the <widget> elements placed directly in a group (the Ikaros 3 form) as one
 *  view: its children are those widgets, read live from the group. */
export const GROUP_WIDGETS = "#widgets";
const groupWidgetViews = new WeakMap();

/** A group's views: its <view> elements, then the "Widgets" view of its own <widget>s. */
export function viewsOf(g) {
    const views = kids(g, "view");
    if (kids(g, "widget").length) {
        if (!groupWidgetViews.has(g)) {
            groupWidgetViews.set(g, {
                tag: GROUP_WIDGETS, attrs: { name: "Widgets" }, group: g,
                get children() { return g.children.filter((c) => c.tag === "widget"); },
            });
        }
        views.push(groupWidgetViews.get(g));
    }
    return views;
}

export function isValidName(name) { return NAME.test(name || ""); }

/** The class of a widget element: <widget class=..>, <object class=..> or <plot ..>. */
export function widgetClassOf(w) {
    const c = (w.tag === "widget" || w.tag === "object") ? (w.attrs.class || "") : w.tag;
    return String(c).replace(/([a-z0-9])([A-Z])/g, "$1-$2").replace(/_/g, "-").toLowerCase();
}

/** Widget geometry, from x/y or _x/_y. */
export function widgetBox(w) {
    const a = w.attrs;
    return {
        x: parseFloat(a.x ?? a._x) || 0, y: parseFloat(a.y ?? a._y) || 0,
        width: parseFloat(a.width) || 200, height: parseFloat(a.height) || 200,
    };
}

export function setWidgetBox(w, box) {
    const a = w.attrs;
    const xKey = a.x === undefined && a._x !== undefined ? "_x" : "x";
    const yKey = a.y === undefined && a._y !== undefined ? "_y" : "y";
    for (const [k, v] of [[xKey, box.x], [yKey, box.y], ["width", box.width], ["height", box.height]]) {
        if (v !== undefined) a[k] = String(Math.round(v));
    }
}

/** First component and the rest of a connection address ("A.OUTPUT[0:2]" -> A, OUTPUT). */
export function splitAddress(text) {
    let t = String(text || "").trim();
    const sel = t.indexOf("[");
    let selector = "";
    if (sel >= 0) { selector = t.slice(sel); t = t.slice(0, sel); }
    const fmt = t.indexOf(":");
    if (fmt >= 0) t = t.slice(0, fmt);
    return { path: t, selector, parts: t.split(".") };
}

export class EditorModel extends EventTarget {
    constructor() {
        super();
        this.tree = null;
        this.file = "";
        this.folder = "";
        this.undoStack = [];
        this.redoStack = [];
        this.dirty = false;        // edited since the last apply
        this.unsaved = false;      // edited since the last save
    }

    load({ tree, file, folder, version }) {
        this.tree = tree;
        this.file = file || "";
        this.folder = folder || "";
        this.version = version ?? null;    // of the file the edits begin from (a save checks it)
        this.undoStack = [];
        this.redoStack = [];
        this.dirty = false;
        this.unsaved = false;
        this.changed("load");
    }

    changed(kind) { this.dispatchEvent(new CustomEvent("change", { detail: kind })); }

    /** Run an edit as one undoable command. fn(tree) changes the tree; it may throw. */
    do(label, fn) {
        const before = JSON.stringify(this.tree);
        let result;
        try {
            result = fn(this.tree);
        } catch (e) {
            this.tree = JSON.parse(before);
            throw e;
        }
        if (JSON.stringify(this.tree) === before) return result;
        this.undoStack.push({ label, tree: before });
        if (this.undoStack.length > 500) this.undoStack.shift();
        this.redoStack = [];
        this.dirty = this.unsaved = true;
        this.changed("edit");
        return result;
    }

    canUndo() { return this.undoStack.length > 0; }
    canRedo() { return this.redoStack.length > 0; }

    undo() {
        const step = this.undoStack.pop();
        if (!step) return;
        this.redoStack.push({ label: step.label, tree: JSON.stringify(this.tree) });
        this.tree = JSON.parse(step.tree);
        this.dirty = this.unsaved = true;
        this.changed("undo");
    }

    redo() {
        const step = this.redoStack.pop();
        if (!step) return;
        this.undoStack.push({ label: step.label, tree: JSON.stringify(this.tree) });
        this.tree = JSON.parse(step.tree);
        this.dirty = this.unsaved = true;
        this.changed("redo");
    }

    // --- finding -----------------------------------------------------------------------

    /** The group node at a dotted path from the top ("" is the top). */
    group(path, tree = this.tree) {
        let g = tree;
        if (!path) return g;
        for (const name of path.split(".")) {
            g = kids(g, "group").find((c) => c.attrs.name === name);
            if (!g) return null;
        }
        return g;
    }

    /** The node at a list of child indices from the root. */
    atIndices(indices) {
        let n = this.tree;
        for (const i of indices || []) {
            n = n?.children?.[i];
            if (!n) return null;
        }
        return n;
    }

    /** The chain of nodes from the root to a node (inclusive), or null. */
    chain(target, n = this.tree, acc = []) {
        acc = [...acc, n];
        if (n === target) return acc;
        for (const c of n.children || []) {
            const found = this.chain(target, c, acc);
            if (found) return found;
        }
        return null;
    }

    byId(id, n = this.tree) {
        if (n.id === id) return n;
        for (const c of n.children || []) {
            const f = this.byId(id, c);
            if (f) return f;
        }
        return null;
    }

    /** Names used by the children of a group (modules and groups). */
    names(g) { return new Set(kids(g).filter((c) => c.tag === "module" || c.tag === "group").map((c) => c.attrs.name)); }

    uniqueName(g, base, taken = this.names(g)) {
        base = (base || "Module").replace(/[^A-Za-z0-9_-]/g, "_").replace(/^([0-9-])/, "_$1");
        if (!taken.has(base)) return base;
        const stem = base.replace(/_?\d+$/, "") || base;
        for (let i = 2; ; i++) if (!taken.has(`${stem}${i}`)) return `${stem}${i}`;
    }

    // --- edits (call inside do) --------------------------------------------------------

    static insert(g, child) {
        // before the connections and views, after the other components
        const i = g.children.findIndex((c) => c.tag === "connection" || c.tag === "view");
        if (child.tag === "connection") {
            const v = g.children.findIndex((c) => c.tag === "view");
            g.children.splice(v < 0 ? g.children.length : v, 0, child);
        } else if (child.tag === "view" || i < 0) g.children.push(child);
        else g.children.splice(i, 0, child);
        return child;
    }

    static remove(parent, child) {
        const i = parent.children.indexOf(child);
        if (i >= 0) parent.children.splice(i, 1);
        return i;
    }

    /** Delete components (children of group g) with every connection that reaches them,
     *  in g or any other group of the tree. */
    static deleteComponents(tree, g, nodes) {
        const gone = new Set(nodes);
        for (const { chain, group } of addressHolders(tree)) {
            for (const c of group.connections) {
                const ends = [c.attrs.source, c.attrs.target].map((t) => componentsOf(chain, t));
                if (ends.some((e) => e.some((s) => gone.has(s.node)))) EditorModel.remove(group.node, c);
            }
        }
        for (const n of nodes) EditorModel.remove(g, n);
    }

    /** Rename component n, and every address in the tree that reaches it (connections, group
     *  port aliases and widget sources, wherever they are written). */
    static rename(tree, n, name) {
        const old = n.attrs.name;
        rewriteAddresses(tree, (chain, t, role) => {
            const parts = splitAddress(t).parts;
            let changed = false;
            for (const s of componentsOf(chain, t, role === "module")) {
                if (s.node === n && parts[s.index] === old) { parts[s.index] = name; changed = true; }
            }
            return changed ? parts : null;
        });
        n.attrs.name = name;
    }

    /** Rename input or output pin of group g, and every address that reaches it: "G.P"
     *  from outside g (directly or by climbing), "P" from inside. Which of an input and an
     *  output of the same name an address means follows from where it is read, as in the
     *  kernel: a source outside g reads an output, inside g an input; a target the other way. */
    static renamePort(tree, g, pin, name) {
        const old = pin.attrs.name;
        rewriteAddresses(tree, (chain, t, role) => {
            if (role === "module") return null;
            const parts = splitAddress(t).parts;
            if (parts[parts.length - 1] !== old) return null;
            let group = chain[chain.length - 1];
            if (parts.length > 1) {
                const found = componentsOf(chain, t);
                if (found.length !== parts.length - 1) return null;
                group = found[found.length - 1].node;
            }
            if (group !== g) return null;
            const inside = chain.includes(g);
            const reads = role === "source" ? (inside ? "input" : "output") : (inside ? "output" : "input");
            if (reads !== pin.tag) return null;
            parts[parts.length - 1] = name;
            return parts;
        });
        pin.attrs.name = name;
    }

    /** Copies of nodes of g (and the connections among them), as a clipboard. */
    static copy(g, nodes) {
        const names = new Set(nodes.map((n) => n.attrs.name));
        const conns = kids(g, "connection").filter((c) =>
            names.has(splitAddress(c.attrs.source).parts[0]) && names.has(splitAddress(c.attrs.target).parts[0]));
        const strip = (n) => { const m = clone(n); const s = (x) => { delete x.id; delete x.file; delete x.line; (x.children || []).forEach(s); }; s(m); return m; };
        return { nodes: nodes.map(strip), connections: conns.map(strip) };
    }

    /** Paste a clipboard into g: names made unique, connections remapped; returns the new nodes. */
    pasteInto(g, clip, offset = 40) {
        // pasted boxes move down and right in 40 px steps until none covers a box there
        // (a box is about 170 x 80, PASTE_ROOM with a margin)
        const pos = (n) => [parseFloat(n.attrs._x) || 0, parseFloat(n.attrs._y) || 0];
        const there = kids(g).filter((c) => c.attrs._x !== undefined).map(pos);
        const placed = clip.nodes.filter((n) => n.attrs._x !== undefined).map(pos);
        const covers = (d) => placed.some(([x, y]) => there.some(([u, v]) =>
            Math.abs(x + d - u) < PASTE_ROOM.w && Math.abs(y + d - v) < PASTE_ROOM.h));
        for (let i = 0; i < 200 && covers(offset); i++) offset += 40;
        const taken = this.names(g);
        const map = new Map();
        const added = [];
        for (const n of clip.nodes) {
            const m = clone(n);
            const name = this.uniqueName(g, m.attrs.name, taken);
            taken.add(name);
            map.set(n.attrs.name, name);
            m.attrs.name = name;
            if (m.attrs._x !== undefined) m.attrs._x = String((parseFloat(m.attrs._x) || 0) + offset);
            if (m.attrs._y !== undefined) m.attrs._y = String((parseFloat(m.attrs._y) || 0) + offset);
            EditorModel.insert(g, m);
            added.push(m);
        }
        const re = (t) => {
            const a = splitAddress(t);
            return [map.get(a.parts[0]) ?? a.parts[0], ...a.parts.slice(1)].join(".") + String(t).trim().slice(a.path.length);
        };
        for (const c of clip.connections) {
            const m = clone(c);
            m.attrs.source = re(m.attrs.source);
            m.attrs.target = re(m.attrs.target);
            EditorModel.insert(g, m);
        }
        return added;
    }
}

const PASTE_ROOM = { w: 190, h: 100 };

/** Widget attributes that hold "Module.PORT" addresses (sources, parameters, commands). */
const WIDGET_ADDRESS = /source$|Source$|parameter$|Parameter$|command|Command/;

function childNamed(g, name) {
    if (g.tag !== "group") return null;
    return kids(g).find((c) => (c.tag === "module" || c.tag === "group") && c.attrs.name === name) || null;
}

/** What the component part of an address (all but its last part, the port; all of it when
 *  ``whole``) names, seen from the last group of chain (groups from the top): [{index, node}]
 *  for each part, by the kernel's rule (a part names a child, or else an enclosing group,
 *  nearest first; a leading "." starts at the top, whose name may follow). Stops where a
 *  part names nothing. */
export function componentsOf(chain, address, whole = false) {
    const all = splitAddress(address).parts;
    const parts = whole ? all : all.slice(0, -1);
    let path = chain, i = 0;
    const out = [];
    if (parts[0] === "" && parts.length > 1) {
        path = [chain[0]];
        i = 1;
        if (parts[1] === (chain[0].attrs.name || "") && !childNamed(chain[0], parts[1])) {
            out.push({ index: 1, node: chain[0] });
            i = 2;
        }
    }
    for (; i < parts.length; i++) {
        const here = path[path.length - 1];
        const child = childNamed(here, parts[i]);
        if (child) {
            path = [...path, child];
        } else {
            let k = path.length - 1;
            while (k >= 0 && path[k].attrs.name !== parts[i]) k--;
            if (k < 0) break;
            path = path.slice(0, k + 1);
        }
        out.push({ index: i, node: path[path.length - 1] });
    }
    return out;
}

/** Every group of the tree with the chain of groups from the top to it, and its editable
 *  elements that hold addresses (those inside an include are read-only and left out). */
function addressHolders(tree) {
    const out = [];
    const visit = (g, chain, readOnly = false) => {
        const here = [...chain, g];
        const own = (tag) => elements(g, tag).filter((e) => !readOnly && !e.readOnly).map((e) => e.node);
        out.push({
            chain: here,
            group: {
                node: g, connections: own("connection"), outputs: own("output"), inputs: own("input"),
                widgets: [...own("view").flatMap((v) => kids(v)), ...own("widget")],
            },
        });
        for (const e of elements(g, "group")) visit(e.node, here, readOnly || e.readOnly);
    };
    visit(tree, []);
    return out;
}

/** Rewrite the editable addresses of the tree. ``change(chain, address, role)`` gets each
 *  address with the chain of groups it is read from and its role ("source", "target" or,
 *  for a widget's module attribute, "module") and returns the new parts of its path, or
 *  null to keep it; selectors and formats after the path are kept. */
function rewriteAddresses(tree, change) {
    const re = (chain, t, role) => {
        const parts = change(chain, t, role);
        return parts ? parts.join(".") + String(t).trim().slice(splitAddress(t).path.length) : t;
    };
    for (const { chain, group } of addressHolders(tree)) {
        for (const c of group.connections) {
            if (c.attrs.source) c.attrs.source = re(chain, c.attrs.source, "source");
            if (c.attrs.target) c.attrs.target = re(chain, c.attrs.target, "target");
        }
        for (const o of group.outputs) if (o.attrs.source) o.attrs.source = re(chain, o.attrs.source, "source");
        for (const i of group.inputs) if (i.attrs.target) i.attrs.target = re(chain, i.attrs.target, "target");
        for (const w of group.widgets) {
            for (const k of Object.keys(w.attrs)) {
                if (k === "module") w.attrs[k] = re(chain, w.attrs[k], "module");
                else if (WIDGET_ADDRESS.test(k) || ["red", "green", "blue", "matrix", "index"].includes(k)) {
                    w.attrs[k] = String(w.attrs[k]).split(",").map((t) => re(chain, t.trim(), "source")).join(",");
                }
            }
        }
    }
}

/** The tree as the navigator's network: {top: {name, path, groups, modules, views}}. */
export function treeAsNetwork(tree) {
    const walk = (g, path) => ({
        name: g.attrs.name || "",
        path,
        modules: kids(g, "module").map((m) => ({ name: m.attrs.name, class: m.attrs.class, path: path ? `${path}.${m.attrs.name}` : m.attrs.name })),
        groups: kids(g, "group").map((s) => walk(s, path ? `${path}.${s.attrs.name}` : s.attrs.name || "")),
        views: kids(g, "view").map((v) => ({ name: v.attrs.name || "", widgets: [] })),
    });
    return { top: walk(tree, "") };
}
