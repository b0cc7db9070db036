// joystick: drag the knob to set two parameters at once (x_parameter, y_parameter; one
// element of each, select_x / select_y, when they are arrays). range bipolar: -1..1, unipolar:
// 0..1; return_to_center (yes) sends the centre when the knob is let go. Keys: arrows
// move the knob by a tenth. For assistive technology it is a slider named by the title (or
// label) whose value is x, and whose value text gives x and y.
import { Widget } from "./widget.js";

export default class Joystick extends Widget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        const pad = document.createElement("div");
        pad.className = "joystick-pad";
        pad.tabIndex = 0;
        pad.setAttribute("role", "slider");
        pad.setAttribute("aria-label", this.str(["title", "label"], "joystick"));
        pad.setAttribute("aria-roledescription", "joystick");
        const knob = document.createElement("div");
        knob.className = "joystick-knob";
        pad.appendChild(knob);
        this.body.appendChild(pad);
        Object.assign(pad.style, { position: "absolute", inset: "6px", borderRadius: "50%", border: "1px solid var(--frame-color)", touchAction: "none" });
        Object.assign(knob.style, { position: "absolute", width: "24px", height: "24px", margin: "-12px 0 0 -12px", borderRadius: "50%", background: "var(--accent)" });
        pad.dataset.control = "";               // its own control, also in the view editor
        this.pad = pad; this.knob = knob;
        this.unipolar = this.str(["range"], "bipolar") === "unipolar";
        pad.setAttribute("aria-valuemin", this.value(-1));
        pad.setAttribute("aria-valuemax", this.value(1));
        this.pos = [0, 0];                      // -1..1 each, y up
        this.place();
        pad.addEventListener("pointerdown", (e) => { pad.setPointerCapture(e.pointerId); this.dragging = true; this.move(e); });
        pad.addEventListener("pointermove", (e) => { if (this.dragging) this.move(e); });
        const up = () => {
            if (!this.dragging) return;
            this.dragging = false;
            if (this.bool(["return_to_center"], true)) { this.pos = [0, 0]; this.place(); this.send(); }
        };
        pad.addEventListener("pointerup", up);
        pad.addEventListener("lostpointercapture", up);
        pad.addEventListener("keydown", (e) => {
            const d = { ArrowLeft: [-0.1, 0], ArrowRight: [0.1, 0], ArrowUp: [0, 0.1], ArrowDown: [0, -0.1] }[e.key];
            if (!d) return;
            e.preventDefault();
            this.pos = this.pos.map((p, i) => Math.max(-1, Math.min(1, p + d[i])));
            this.place(); this.send();
        });
    }

    move(e) {
        const r = this.pad.getBoundingClientRect();
        let x = ((e.clientX - r.left) / r.width) * 2 - 1, y = 1 - ((e.clientY - r.top) / r.height) * 2;
        const L = Math.hypot(x, y);
        if (L > 1) { x /= L; y /= L; }
        this.pos = [x, y];
        this.place();
        this.send();
    }

    place() {
        this.knob.style.left = ((this.pos[0] + 1) / 2) * 100 + "%";
        this.knob.style.top = ((1 - this.pos[1]) / 2) * 100 + "%";
        const [x, y] = this.pos.map((p) => this.value(p));
        this.pad.setAttribute("aria-valuenow", x);
        this.pad.setAttribute("aria-valuetext", `x ${x.toFixed(2)}, y ${y.toFixed(2)}`);
    }

    /** The value sent for a knob position -1..1. */
    value(p) { return this.unipolar ? (p + 1) / 2 : p; }

    send() {
        if (this.sending) { this.again = true; return; }      // only the newest position
        this.sending = true;
        const x = this.int(["select_x"], 0), y = this.int(["select_y"], 0);
        const jobs = [["x_parameter", 0], ["y_parameter", 1]].map(([attr, i]) => {
            const p = this.path(attr);
            return p ? this.setParameter(p, this.value(this.pos[i]), this.raw(["select_x"]) !== undefined ? x : undefined,
                this.raw(["select_y"]) !== undefined ? y : undefined) : null;
        });
        Promise.all(jobs).finally(() => { this.sending = false; if (this.again) { this.again = false; this.send(); } });
    }
}
