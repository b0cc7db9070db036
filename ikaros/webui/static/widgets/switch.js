// switch: check boxes bound to parameter elements.
// Attributes: parameter, label|labels, value (the "on" value, 1), xindex|select_x,
// yindex|select_y, control_count (several switches on consecutive x), enableSource|
// enabled_source. Disabled until the parameter's value has arrived. A box without a label
// is named by the title, else the parameter (with the element's index when there are several).
import { Widget } from "./widget.js";

export default class Switch extends Widget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        this.x = this.int(["xindex", "select_x", "select"], 0);
        this.y = this.int(["yindex", "select_y"], 0);
        const n = Math.max(1, this.int(["control_count", "count"], 1));
        const labels = this.list(["labels", "label"], []);
        this.boxes = [];
        this.paramValue = null;
        for (let i = 0; i < n; i++) {
            const lab = document.createElement("label");
            lab.className = "switch";
            const box = document.createElement("input");
            box.type = "checkbox";
            if (!labels[i]) box.setAttribute("aria-label", this.controlName("", n > 1 ? this.x + i : null));
            box.addEventListener("change", () => this.changed(i, box.checked));
            const span = document.createElement("span");
            span.textContent = labels[i] ?? "";
            lab.append(box, span);
            this.body.appendChild(lab);
            this.boxes.push(box);
        }
        this.setControlsDisabled(this.boxes);
    }

    parameters() { const p = this.path("parameter"); return p ? [p] : []; }
    subscriptions() { return this.enabledSubscription(); }

    async changed(i, on) {
        const p = this.path("parameter");
        if (!p) return;
        const on_ = this.num(["value"], 1);
        const isArray = Array.isArray(this.paramValue) || this.boxes.length > 1;
        const isBool = typeof this.paramValue === "boolean";
        const value = isBool ? on : on ? on_ : 0;
        const a = await this.setParameter(p, value, isArray ? this.x + i : undefined, isArray ? this.y : undefined);
        if (a) this.setParameters(new Map([[p, a.value]]));
    }

    setParameters(values) {
        const p = this.path("parameter");
        if (!values.has(p)) return;
        this.paramValue = values.get(p);
        const on_ = this.num(["value"], 1);
        this.boxes.forEach((box, i) => {
            const v = Widget.element(this.paramValue, this.x + i, this.y);
            box.checked = v === true || Number(v) === on_ || (typeof v === "string" && /^(yes|true|1)$/i.test(v));
        });
        this.setControlsDisabled(this.boxes);
    }

    update(frame) { this.enabled = this.enabledFrom(frame); this.setControlsDisabled(this.boxes); }
}
