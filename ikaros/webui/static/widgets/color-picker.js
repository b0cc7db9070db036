// color-picker: sets a parameter of three values 0..1 (red, green, blue; a row of a
// matrix parameter with row_source... or select_y) from the browser's colour chooser, and
// shows the parameter's current colour.
// Attributes: parameter, select_y (the row of a matrix parameter), show_values (yes).
import { Widget } from "./widget.js";

const hex2 = (v) => Math.round(Math.max(0, Math.min(1, Number(v) || 0)) * 255).toString(16).padStart(2, "0");

export default class ColorPicker extends Widget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        const input = document.createElement("input");
        input.type = "color";
        input.className = "color-picker";
        input.setAttribute("aria-label", this.str(["title", "label"], "colour"));
        this.values = document.createElement("div");
        this.values.className = "color-values";
        this.body.append(input, this.values);
        this.input = input;
        this.paramValue = null;
        input.addEventListener("input", () => this.send());
        this.setControlsDisabled([input]);
    }

    parameters() { const p = this.path("parameter"); return p ? [p] : []; }

    row(value) {
        if (!Array.isArray(value)) return [value, value, value];
        if (Array.isArray(value[0])) return value[this.int(["select_y"], 0)] || value[0];
        return value;
    }

    setParameters(values) {
        const p = this.path("parameter");
        if (!values.has(p)) return;
        this.paramValue = values.get(p);
        const [r, g, b] = this.row(this.paramValue);
        if (document.activeElement !== this.input) this.input.value = "#" + hex2(r) + hex2(g) + hex2(b);
        if (this.bool(["show_values"], true)) this.values.textContent = [r, g, b].map((v) => Number(v).toFixed(2)).join(" ");
        this.setControlsDisabled([this.input]);
    }

    async send() {
        const p = this.path("parameter");
        if (!p || this.paramValue === null) return;
        const h = this.input.value;
        const rgb = [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16) / 255);
        let value = rgb;
        if (Array.isArray(this.paramValue) && Array.isArray(this.paramValue[0])) {
            const y = this.int(["select_y"], 0);
            value = this.paramValue.map((row, i) => (i === y ? rgb : row));
        }
        const a = await this.setParameter(p, value);
        if (a) this.setParameters(new Map([[p, a.value]]));
    }
}
