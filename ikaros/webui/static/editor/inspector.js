// The editor's inspector: the attributes of the selected module, group, connection, group
// input or output, or widget, each with the control its type needs (number, checkbox, menu
// for options, text, matrix). Every change is one undoable edit through ctx.edit.
import { isValidName, splitAddress, widgetClassOf } from "./model.js";
import { SPELLINGS, templateOf } from "../widgets/templates.js";
import { viewXml } from "../view-xml.js";
import { descriptionElement, plainText } from "../describe.js";

const NOT_WIDGETS = new Set(["module", "group", "connection", "input", "output", "parameter", "view", "define", "description"]);

function h(tag, cls, text) {
    const e = document.createElement(tag);
    if (cls) e.className = cls;
    if (text !== undefined) e.textContent = text;
    return e;
}

const HIDDEN = new Set(["_x", "_y"]);
const isNumber = (t) => t !== "" && t !== undefined && t !== null && !isNaN(Number(t));

export class EditorInspector {
    /** ctx: {edit(label, fn), rename(node, name), classes(), sources(), parameters(), error(node)} */
    constructor(el, ctx) {
        this.el = el;
        this.ctx = ctx;
    }

    clear() { this.el.textContent = ""; }

    show(selection, context) {
        this.clear();
        const title = h("div", "pane-title", "Edit");
        this.el.appendChild(title);
        if (selection.length !== 1) {
            this.el.appendChild(h("div", "dialog-note", selection.length ? `${selection.length} selected` :
                "Select a box, a connection or a widget. Double-click a group to open it."));
            if (context?.group) this.groupPanel(context.group, true);
            return;
        }
        const n = selection[0];
        const err = this.ctx.error(n);
        if (err) this.el.appendChild(h("div", "editor-error", err));
        if (context?.readOnly) this.el.appendChild(h("div", "dialog-note", "included from another file: read-only"));
        if (n.tag === "module") this.modulePanel(n);
        else if (n.tag === "group") this.groupPanel(n, false);
        else if (n.tag === "connection") this.connectionPanel(n);
        else if (n.tag === "input" || n.tag === "output") this.pinPanel(n);
        else this.widgetPanel(n);
        if (context?.readOnly) {
            for (const field of this.el.querySelectorAll("input, select, textarea, button")) field.disabled = true;
        }
    }

    table(title) {
        if (title) this.el.appendChild(h("div", "section-title", title));
        const t = h("table", "inspector-table editor-table");
        this.el.appendChild(t);
        return t;
    }

    row(t, label, control, tip = "") {
        const tr = t.insertRow();
        const l = tr.insertCell();
        l.textContent = label;
        l.title = tip;
        const c = tr.insertCell();
        c.appendChild(control);
        // the field's accessible name is its label
        const field = control.matches?.("input, select, textarea") ? control : control.querySelector?.("input, select, textarea");
        if (field && !field.hasAttribute("aria-label")) field.setAttribute("aria-label", label);
        return tr;
    }

    nameField(n) {
        const input = h("input", "param-input");
        input.value = n.attrs.name || "";
        input.dataset.attr = "name";
        input.addEventListener("change", () => {
            const name = input.value.trim();
            if (!isValidName(name)) { input.classList.add("invalid"); input.title = "letters, digits, _ and -, not starting with a digit"; return; }
            this.ctx.rename(n, name);
        });
        return input;
    }

    /** A text attribute; empty removes it. */
    text(n, key, { area = false, placeholder = "" } = {}) {
        const input = h(area ? "textarea" : "input", "param-input");
        input.value = n.attrs[key] ?? "";
        input.placeholder = placeholder;
        input.dataset.attr = key;
        input.addEventListener("change", () => this.set(n, key, input.value));
        return input;
    }

    set(n, key, value) {
        this.ctx.edit(`set ${key}`, () => {
            if (value === null || value === undefined || value === "") delete n.attrs[key];
            else n.attrs[key] = String(value);
        });
    }

    /** The control for one parameter of a class. */
    parameter(n, p) {
        const key = p.name;
        const value = n.attrs[key];
        const def = p.default === null || p.default === undefined ? "" : String(p.default);
        let input;
        if (p.type === "bool" && (value === undefined || /^(true|false|yes|no|1|0|on|off)$/i.test(value))) {
            input = h("input", "param-input");
            input.type = "checkbox";
            input.checked = /^(true|yes|1|on)$/i.test(value ?? def);
            input.addEventListener("change", () => this.set(n, key, input.checked ? "true" : "false"));
        } else if (p.options && p.options.length) {
            input = h("select", "param-input");
            input.add(new Option(`(default: ${def})`, ""));
            for (const o of p.options) input.add(new Option(o, o));
            if (value !== undefined && !p.options.includes(value)) input.add(new Option(value, value));
            input.value = value ?? "";
            input.addEventListener("change", () => this.set(n, key, input.value));
        } else if ((p.type === "number" || p.type === "int") && (value === undefined || isNumber(value))) {
            input = h("input", "param-input");
            input.type = "number";
            input.step = p.type === "int" ? "1" : "any";
            input.value = value ?? "";
            input.placeholder = def;
            input.addEventListener("change", () => this.set(n, key, input.value));
        } else if (p.type === "matrix" || p.type === "array") {
            input = h("textarea", "param-input matrix-input");
            input.rows = 2;
            input.value = value ?? "";
            input.placeholder = def || "1 2 3; 4 5 6";
            input.addEventListener("change", () => this.set(n, key, input.value.trim()));
        } else {
            input = h("input", "param-input");
            input.value = value ?? "";
            input.placeholder = def;
            input.addEventListener("change", () => this.set(n, key, input.value));
        }
        input.dataset.param = key;
        input.dataset.type = p.type;
        return input;
    }

    extraAttributes(n, known) {
        const t = this.table("Other attributes");
        for (const key of Object.keys(n.attrs)) {
            if (known.has(key) || HIDDEN.has(key)) continue;
            const input = this.text(n, key);
            const tr = this.row(t, key, input);
            const del = h("button", "close", "×");
            del.title = "remove " + key;
            del.addEventListener("click", () => this.set(n, key, null));
            tr.insertCell().appendChild(del);
        }
        const add = h("button", "tool small", "+ attribute");
        add.className += " add-attribute";
        add.addEventListener("click", () => {
            const key = prompt("Attribute name");
            if (key && /^[A-Za-z_][\w.-]*$/.test(key)) this.set(n, key, prompt("Value", "") ?? "");
        });
        this.el.appendChild(add);
    }

    modulePanel(n) {
        const desc = this.ctx.classes()[n.attrs.class];
        this.el.appendChild(h("div", "module-class", n.attrs.class || "(no class)"));
        if (desc?.description) this.el.appendChild(descriptionElement("div", "module-description", desc.description));
        const t = this.table();
        this.row(t, "name", this.nameField(n));
        const params = desc?.parameters || [];
        if (params.length) {
            const pt = this.table("Parameters");
            for (const p of params) {
                const tr = this.row(pt, p.name, this.parameter(n, p), `${p.type}: ${plainText(p.description)}`);
                if (n.attrs[p.name] !== undefined) {
                    const reset = h("button", "close", "↺");
                    reset.title = "use the default";
                    reset.addEventListener("click", () => this.set(n, p.name, null));
                    tr.insertCell().appendChild(reset);
                }
            }
        }
        this.extraAttributes(n, new Set(["name", "class", ...params.map((p) => p.name)]));
    }

    groupPanel(n, current) {
        this.el.appendChild(h("div", "module-class", current ? `group ${n.attrs.name || ""} (open)` : "group"));
        const t = this.table();
        this.row(t, "name", this.nameField(n));
        this.row(t, "description", this.text(n, "description", { area: true }));
        this.extraAttributes(n, new Set(["name", "description"]));
    }

    connectionPanel(n) {
        this.el.appendChild(h("div", "module-class", "connection"));
        const t = this.table();
        const src = splitAddress(n.attrs.source), dst = splitAddress(n.attrs.target);
        this.row(t, "source", this.text(n, "source"));
        this.row(t, "target", this.text(n, "target"));
        const delay = this.text(n, "delay", { placeholder: "1" });
        delay.title = "ticks: a number, a list 1,3 or a range 1:3";
        this.row(t, "delay", delay, "the delay in ticks (default 1)");
        const range = (addr, key) => {
            const input = h("input", "param-input");
            input.value = addr.selector;
            input.placeholder = "[a:b] (all)";
            input.dataset.attr = key;
            input.addEventListener("change", () => {
                let s = input.value.trim();
                if (s && !s.startsWith("[")) s = `[${s}]`;
                this.set(n, key === "source-range" ? "source" : "target", addr.path + s);
            });
            return input;
        };
        this.row(t, "source range", range(src, "source-range"), "a selector such as [0:2] or [1][0:3]");
        this.row(t, "target range", range(dst, "target-range"), "a selector such as [0:2]");
        this.extraAttributes(n, new Set(["source", "target", "delay"]));
    }

    pinPanel(n) {
        this.el.appendChild(h("div", "module-class", `group ${n.tag}`));
        const t = this.table();
        this.row(t, "name", this.nameField(n));
        if (n.tag === "output") this.row(t, "source", this.text(n, "source", { placeholder: "(set by a connection)" }));
        this.extraAttributes(n, new Set(["name", "source"]));
    }

    /** Bring to front, send to back (the order of the view's elements is the drawing
     *  order) and copy the view as XML. */
    widgetActions(n) {
        const bar = h("div", "widget-actions");
        const move = (label, toFront) => {
            const b = h("button", "tool small", label);
            b.dataset.action = toFront ? "to-front" : "to-back";
            b.addEventListener("click", () => {
                const parent = this.ctx.parentOf(n);
                if (!parent) return;
                this.ctx.edit(label.toLowerCase(), () => {
                    const i = parent.children.indexOf(n);
                    parent.children.splice(i, 1);
                    // the drawing order counts only widgets: a widget goes before or after them all
                    const widgets = parent.children.map((c, k) => [c, k]).filter(([c]) => !c.tag.startsWith("#") && !NOT_WIDGETS.has(c.tag));
                    const at = toFront ? (widgets.length ? widgets[widgets.length - 1][1] + 1 : parent.children.length) : (widgets.length ? widgets[0][1] : 0);
                    parent.children.splice(at, 0, n);
                });
            });
            return b;
        };
        const copy = h("button", "tool small", "Copy view as XML");
        copy.dataset.action = "copy-xml";
        copy.addEventListener("click", async () => {
            const parent = this.ctx.parentOf(n);
            if (!parent) return;
            try { await navigator.clipboard.writeText(viewXml(parent)); copy.textContent = "Copied"; }
            catch (e) { copy.textContent = "Copy failed: " + e.message; }
        });
        bar.append(move("To front", true), move("To back", false), copy);
        this.el.appendChild(bar);
    }

    /** A control for a widget attribute of a type from widgets/templates.js. */
    typed(n, key, type, searchable) {
        const value = n.attrs[key] ?? "";
        const menu = (choices) => {
            const s = h("select", "param-input");
            s.dataset.attr = key;
            s.add(new Option("(default)", ""));
            for (const x of choices) s.add(new Option(x, x));
            if (value && !choices.includes(value)) s.add(new Option(value, value));
            s.value = value;
            s.addEventListener("change", () => this.set(n, key, s.value));
            return s;
        };
        if (Array.isArray(type)) return menu(type);
        if (type === "bool") return menu(["yes", "no"]);
        if (type === "source") return searchable(menu(this.ctx.sources()));
        if (type === "parameter") return menu(this.ctx.parameters());
        const input = this.text(n, key);
        if (type === "number" || type === "int") {
            input.type = "number";
            input.step = type === "int" ? "1" : "any";
            return input;
        }
        if (type !== "color") return input;
        const box = h("div", "color-field");
        const swatch = h("input", "color-swatch");
        swatch.type = "color";
        swatch.setAttribute("aria-label", `${key} colour`);
        const c = document.createElement("canvas").getContext("2d");
        c.fillStyle = value.split(",")[0] || "#000000";
        swatch.value = c.fillStyle.startsWith("#") ? c.fillStyle : "#000000";
        swatch.addEventListener("change", () => this.set(n, key, swatch.value));
        box.append(input, swatch);
        return box;
    }

    widgetPanel(n) {
        // a menu with a search field above it that keeps only the options holding its words
        const searchable = (select) => {
            const box = h("div", "searchable-pick");
            const find = h("input", "param-input");
            find.type = "search";
            find.placeholder = "search";
            find.dataset.search = select.dataset.attr;
            find.setAttribute("aria-label", `search ${select.dataset.attr}`);
            find.addEventListener("input", () => {
                const words = find.value.toLowerCase().split(/\s+/).filter(Boolean);
                for (const o of select.options) o.hidden = o.value !== "" && !words.every((w) => o.value.toLowerCase().includes(w));
            });
            box.append(find, select);
            return box;
        };
        const cls = widgetClassOf(n);
        this.el.appendChild(h("div", "module-class", `widget: ${cls}`));
        const t = this.table();
        this.row(t, "title", this.text(n, "title"));
        const pick = (key, list) => {
            const s = h("select", "param-input");
            s.dataset.attr = key;
            s.add(new Option("(none)", ""));
            const value = n.attrs[key] ?? "";
            for (const x of list) s.add(new Option(x, x));
            if (value && !list.includes(value)) s.add(new Option(value, value));
            s.value = value;
            s.addEventListener("change", () => this.set(n, key, s.value));
            return s;
        };
        this.row(t, "source", searchable(pick("source", this.ctx.sources())), "an output of any module (a leading . starts at the top group)");
        if ("parameter" in n.attrs || ["slider-horizontal", "slider-vertical", "switch", "drop-down-menu", "button", "text", "grid"].includes(cls)) {
            this.row(t, "parameter", pick("parameter", this.ctx.parameters()), "a parameter in this group");
        }
        for (const key of ["x", "y", "width", "height"]) {
            const k = key in n.attrs ? key : (`_${key}` in n.attrs ? `_${key}` : key);
            const input = this.text(n, k);
            input.type = "number";
            this.row(t, key, input);
        }
        const st = this.table("Style");
        const color = this.text(n, "color", { placeholder: "e.g. red, #2a7ab9, or a list" });
        this.row(st, "color", color);
        for (const key of ["show_title", "show_frame"]) {
            const c = h("input", "param-input");
            c.type = "checkbox";
            c.dataset.attr = key;
            c.checked = !/^(false|no|0|off)$/i.test(n.attrs[key] ?? "true");
            c.addEventListener("change", () => this.set(n, key, c.checked ? "true" : "false"));
            this.row(st, key.replace("_", " "), c);
        }
        this.row(st, "style", this.text(n, "style", { placeholder: "CSS, e.g. background: #eef" }));
        const known = new Set(["class", "title", "source", "parameter", "x", "y", "_x", "_y", "width", "height", "color", "show_title", "show_frame", "style"]);
        const wt = this.table("Widget");
        for (const [name, type] of templateOf(cls)) {
            const key = [name, ...(SPELLINGS[name] || [])].find((k) => k in n.attrs) ?? name;
            if (known.has(key)) continue;
            known.add(key);
            this.row(wt, name, this.typed(n, key, type, searchable));
        }
        this.extraAttributes(n, known);
        this.widgetActions(n);
    }
}
