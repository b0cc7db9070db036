// slider-horizontal (and, through a subclass, slider-vertical): one or many sliders bound to
// parameter elements.
// Attributes: parameter, command (v3: also sends the command with the value), select|
// select_x (the first element), count|control_count (sliders for elements select+i),
// select_y (row), labels, min (0), max (1), step (0.01), show_values, enabled_source.
// A slider bound to a parameter is disabled until the parameter's value has arrived. Each
// is a range input (the slider role, its value, minimum and maximum) named by its label,
// else the title, else the parameter (with the element's index when there are several).
import { Widget, formatNumber } from "./widget.js";

export default class SliderHorizontal extends Widget {
    static vertical = false;

    constructor(attrs, ctx) {
        super(attrs, ctx);
        const vertical = this.constructor.vertical;
        this.body.classList.add("sliders", vertical ? "vertical" : "horizontal");
        this.first = this.int(["select", "select_x", "xindex"], 0);
        this.row = this.raw(["select_y", "yindex"]);
        this.count = Math.max(1, this.int(["count", "control_count"], 1));
        const labels = this.list(["labels"], []);
        const min = this.num(["min"], 0), max = this.num(["max"], 1), step = this.num(["step"], 0.01);
        this.showValues = this.bool(["show_values"], true);
        this.paramValue = null;
        this.inputs = [];
        this.outputs = [];
        this.dragging = new Set();
        for (let i = 0; i < this.count; i++) {
            const row = document.createElement("div");
            row.className = "slider";
            const label = document.createElement("span");
            label.className = "slider-label";
            label.textContent = labels[i] ?? "";
            const input = document.createElement("input");
            input.type = "range";
            input.min = min; input.max = max; input.step = step;
            input.value = min;
            if (vertical) { input.setAttribute("orient", "vertical"); input.setAttribute("aria-orientation", "vertical"); }
            input.setAttribute("aria-label", this.controlName(labels[i], this.count > 1 ? this.first + i : null));
            const out = document.createElement("span");
            out.className = "slider-value";
            out.hidden = !this.showValues;
            input.addEventListener("pointerdown", () => this.dragging.add(i));
            input.addEventListener("pointerup", () => this.dragging.delete(i));
            input.addEventListener("input", () => this.moved(i, parseFloat(input.value)));
            input.addEventListener("change", () => { this.dragging.delete(i); this.moved(i, parseFloat(input.value), true); });
            row.append(label, input, out);
            this.body.appendChild(row);
            this.inputs.push(input);
            this.outputs.push(out);
        }
        this.pending = new Map();
        this.busy = false;
        this.setControlsDisabled(this.inputs);
    }

    isArray() { return Array.isArray(this.paramValue) || this.count > 1 || this.attrs.select !== undefined || this.attrs.select_x !== undefined; }

    moved(i, value, final = false) {
        this.outputs[i].textContent = formatNumber(value, 2);
        this.pending.set(i, value);
        this.flush();
    }

    /** Send the newest value of each moved slider, one request at a time. */
    async flush() {
        if (this.busy) return;
        this.busy = true;
        try {
            while (this.pending.size) {
                const [i, value] = this.pending.entries().next().value;
                this.pending.delete(i);
                const p = this.path("parameter");
                if (p) {
                    const x = this.isArray() ? this.first + i : undefined;
                    const y = Array.isArray(this.paramValue?.[0]) ? parseInt(this.row ?? 0, 10) : undefined;
                    await this.setParameter(p, value, x, y);
                }
                const command = this.commandTarget("command");
                if (command) await this.sendCommand(command, this.first + i, parseInt(this.row ?? 0, 10), value);
            }
        } finally {
            this.busy = false;
        }
    }

    parameters() { const p = this.path("parameter"); return p ? [p] : []; }
    subscriptions() { return this.enabledSubscription(); }

    setParameters(values) {
        const p = this.path("parameter");
        if (!values.has(p)) return;
        this.paramValue = values.get(p);
        this.inputs.forEach((input, i) => {
            if (this.dragging.has(i) || this.pending.has(i) || document.activeElement === input && this.busy) return;
            const v = Number(Widget.element(this.paramValue, this.first + i, parseInt(this.row ?? 0, 10)));
            if (Number.isFinite(v)) { input.value = v; this.outputs[i].textContent = formatNumber(v, 2); }
        });
        this.setControlsDisabled(this.inputs);
    }

    update(frame) { this.enabled = this.enabledFrom(frame); this.setControlsDisabled(this.inputs); }
}
