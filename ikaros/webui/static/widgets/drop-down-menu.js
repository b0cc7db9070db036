// drop-down-menu: selects an option for a parameter.
// Attributes: parameter, list|options (comma list, "X,Y,Z"), value_type (number: sends the
// option's index; string: sends its text; by default string for string parameters),
// index|select_x (element), label, labelWidth|label_width, enabled_source. Disabled until
// the parameter's value has arrived. The menu is named by its label, else the title, else
// the parameter.
import { Widget } from "./widget.js";

export default class DropDownMenu extends Widget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        this.body.classList.add("drop-down-body");
        const label = this.str(["label"]);
        if (label) {
            const l = document.createElement("span");
            l.className = "drop-down-label";
            l.textContent = label;
            l.style.width = this.num(["labelWidth", "label_width"], 50) + "px";
            this.body.appendChild(l);
        }
        this.select = document.createElement("select");
        this.select.setAttribute("aria-label", this.controlName(label));
        this.options = this.list(["list", "options"], ["X", "Y", "Z"]);
        this.options.forEach((o, i) => { const opt = new Option(o, String(i)); this.select.add(opt); });
        this.body.appendChild(this.select);
        this.x = this.raw(["index", "select_x", "xindex"]);
        this.paramValue = null;
        this.select.addEventListener("change", () => this.changed());
        this.setControlsDisabled([this.select]);
    }

    valueType() {
        const t = this.str(["value_type"], "");
        if (t) return t;
        return typeof this.paramValue === "string" ? "string" : "number";
    }

    async changed() {
        const p = this.path("parameter");
        if (!p) return;
        const i = this.select.selectedIndex;
        const value = this.valueType() === "string" ? this.options[i] : i;
        const x = Array.isArray(this.paramValue) ? parseInt(this.x ?? 0, 10) : undefined;
        const a = await this.setParameter(p, value, x);
        if (a) this.setParameters(new Map([[p, a.value]]));
    }

    parameters() { const p = this.path("parameter"); return p ? [p] : []; }
    subscriptions() { return this.enabledSubscription(); }

    setParameters(values) {
        const p = this.path("parameter");
        if (!values.has(p)) return;
        this.paramValue = values.get(p);
        const v = Widget.element(this.paramValue, parseInt(this.x ?? 0, 10), 0);
        const i = typeof v === "string" && isNaN(Number(v)) ? this.options.indexOf(v) : Number(v);
        if (i >= 0 && i < this.options.length && document.activeElement !== this.select) this.select.selectedIndex = i;
        this.setControlsDisabled([this.select]);
    }

    update(frame) { this.enabled = this.enabledFrom(frame); this.setControlsDisabled([this.select]); }
}
