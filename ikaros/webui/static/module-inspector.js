// The module inspector: class, description, parameters (editable live), inputs and outputs
// with their shapes and current values, and the module's own view when its class has one.
import { api } from "./api.js";
import { ViewRenderer } from "./views.js";
import { describe, plainText } from "./describe.js";

function valueText(v, decimals = 4) {
    // lines break only between numbers (after ", "), never inside one (base.css)
    if (Array.isArray(v)) {
        if (v.length && Array.isArray(v[0])) return v.map((r) => valueText(r, decimals)).join("; ");
        return v.map((x) => valueText(x, decimals)).join(", ");
    }
    if (typeof v === "number") return Number.isInteger(v) ? String(v) : v.toFixed(decimals).replace(/0+$/, "").replace(/\.$/, "");
    if (v === null || v === undefined) return "";
    return String(v);
}

function optionList(p) {
    if (Array.isArray(p.options)) return p.options;
    if (typeof p.options === "string" && p.options) return p.options.split(/[\/,]/);
    return [];
}

export class ModuleInspector {
    constructor(el, { notify, ctx, onViewChange }) {
        this.el = el;
        this.notify = notify;
        this.ctx = ctx;
        this.onViewChange = onViewChange;
        this.path = null;
        this.view = null;
        this.timer = null;
    }

    async open(path) {
        this.close();
        this.path = path;
        this.el.hidden = false;
        let info;
        try {
            info = await api.module(path);
        } catch (e) {
            this.notify("error", `module ${path}: ${e.message}`);
            return;
        }
        if (this.path !== path) return;
        this.info = info;
        this.render(info);
        // below the System inspector it would open out of sight: bring it up and focus it
        this.el.tabIndex = -1;
        this.el.setAttribute("aria-label", `module ${path}`);
        this.el.scrollIntoView({ block: "start" });
        this.el.focus({ preventScroll: true });
        this.refresh();
        this.timer = setInterval(() => this.refresh(), 500);
    }

    close() {
        clearInterval(this.timer);
        this.timer = null;
        if (this.view) { this.view.destroy(); this.view = null; this.onViewChange(); }
        this.path = null;
        this.el.textContent = "";
        this.el.hidden = true;
    }

    section(title) {
        const h = document.createElement("div");
        h.className = "section-title";
        h.textContent = title;
        this.el.appendChild(h);
        const t = document.createElement("table");
        t.className = "inspector-table";
        this.el.appendChild(t);
        return t;
    }

    render(info) {
        this.el.textContent = "";
        const head = document.createElement("div");
        head.className = "pane-title";
        head.textContent = info.path;
        const x = document.createElement("button");
        x.className = "close";
        x.textContent = "×";
        x.title = "close";
        x.addEventListener("click", () => this.close());
        head.appendChild(x);
        this.el.appendChild(head);
        const cls = document.createElement("div");
        cls.className = "module-class";
        cls.textContent = info.class;
        this.el.appendChild(cls);
        if (info.description) {
            const d = document.createElement("div");
            d.className = "module-description";
            d.append(...describe(info.description));
            this.el.appendChild(d);
        }
        this.paramInputs = {};
        const pt = this.section("Parameters");
        for (const p of info.parameters || []) {
            const tr = pt.insertRow();
            const name = tr.insertCell();
            name.textContent = p.name;
            name.title = plainText(p.description);
            const td = tr.insertCell();
            td.appendChild(this.editor(p));
        }
        this.valueCells = {};
        for (const [title, list, kind] of [["Inputs", info.inputs || [], "input"], ["Outputs", info.outputs || [], "output"]]) {
            if (!list.length) continue;
            const t = this.section(title);
            for (const b of list) {
                const tr = t.insertRow();
                const n = tr.insertCell();
                n.textContent = b.name;
                n.title = plainText(b.description);
                tr.insertCell().textContent = "[" + (b.shape || []).join(" × ") + "]" + (kind === "input" && b.connected === false ? " (unconnected)" : "");
                const v = tr.insertCell();
                v.className = "buffer-value";
                v.dataset.buffer = `${info.path}.${b.name}`;
                this.valueCells[`${info.path}.${b.name}`] = v;
            }
        }
        if (info.view && (info.view.widgets || []).length) {
            const h = document.createElement("div");
            h.className = "section-title";
            h.textContent = "View";
            this.el.appendChild(h);
            const box = document.createElement("div");
            box.className = "module-view";
            this.el.appendChild(box);
            const group = info.path.split(".").slice(0, -1).join(".");
            this.view = new ViewRenderer(box, info.view, { ...this.ctx, groupPath: group });
            this.view.build().then(() => this.onViewChange());
        }
    }

    editor(p) {
        const options = optionList(p);
        let input;
        const send = async (value) => {
            try {
                const a = await api.setParameter(`${this.path}.${p.name}`, value);
                this.setInput(p, a.value);
            } catch (e) {
                this.notify("error", `${p.name}: ${e.message}`);
                input.classList.add("invalid");
            }
        };
        if (p.type === "bool" || typeof p.value === "boolean") {
            input = document.createElement("input");
            input.type = "checkbox";
            input.addEventListener("change", () => send(input.checked));
        } else if (options.length) {
            input = document.createElement("select");
            for (const o of options) input.add(new Option(o, o));
            input.addEventListener("change", () => send(p.type === "int" || p.type === "number" ? input.selectedIndex : input.value));
        } else {
            input = document.createElement("input");
            input.type = "text";
            input.addEventListener("change", () => {
                input.classList.remove("invalid");
                const t = input.value.trim();
                let v = t;
                if ((p.type === "number" || p.type === "float" || p.type === "double") && t !== "" && !isNaN(Number(t))) v = Number(t);
                else if (p.type === "int" && /^[+-]?\d+$/.test(t)) v = parseInt(t, 10);
                send(v);
            });
        }
        input.className = (input.className + " param-input").trim();
        input.dataset.param = p.name;
        this.paramInputs[p.name] = input;
        this.setInput(p, p.value);
        return input;
    }

    setInput(p, value) {
        const input = this.paramInputs[p.name];
        if (!input || document.activeElement === input) return;
        if (input.type === "checkbox") input.checked = value === true || value === 1 || /^(yes|true|1)$/i.test(String(value));
        else if (input.tagName === "SELECT") {
            const opts = optionList(p);
            const i = typeof value === "number" ? value : opts.indexOf(String(value));
            if (i >= 0) input.selectedIndex = i;
        } else input.value = valueText(value, 6);
    }

    async refresh() {
        const path = this.path;
        if (!path) return;
        try {
            const info = await api.module(path);
            if (this.path !== path) return;
            for (const p of info.parameters || []) this.setInput(p, p.value);
        } catch { }
        const outputs = (this.info.outputs || []).map((b) => `${path}.${b.name}`);
        const inputs = (this.info.inputs || []).filter((b) => b.connected !== false).map((b) => `${path}.${b.name}`);
        for (const paths of [outputs, inputs]) {
            if (!paths.length) continue;
            try {
                const d = await api.data(paths);
                if (this.path !== path) return;
                for (const [k, v] of Object.entries(d.data || {})) {
                    const cell = this.valueCells[k];
                    if (cell) cell.textContent = valueText(v, 4);
                }
            } catch { }
        }
    }
}
