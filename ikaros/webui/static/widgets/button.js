// button: runs a command or sets a parameter.
// Attributes: label, command (sent on press), commandUp|release_command (on release),
// parameter with value (1, on press) and valueUp|release_value (0, on release),
// type (push: value while held; toggle: flips the parameter between value and
// release_value; radio: sets value, on while the parameter has it, so buttons of one
// parameter with different values form a group; multi: steps the parameter through
// "values" (0,1,2) and shows the matching one of "labels"),
// xindex|select_x, yindex|select_y (the element), enableSource|enabled_source (disabled while
// its [0][0] is 0), text_color, background_color, tooltip.
import { Widget } from "./widget.js";

// a widget lower than this shows its button without the title bar: the title would leave
// the button too low for its label (title bar 17 px, button 28 px with its margins)
const ROOM_FOR_TITLE = 48;

export default class Button extends Widget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        if (this.titleEl && this.num(["height"], ROOM_FOR_TITLE) < ROOM_FOR_TITLE) {
            this.titleEl.remove();
            this.titleEl = null;
        }
        const b = document.createElement("button");
        b.className = "button-control";
        b.textContent = this.str(["label"], this.str(["title"], "Button"));
        const tc = this.str(["text_color"]); if (tc) b.style.color = tc;
        const bg = this.str(["background_color"]); if (bg) b.style.background = bg;
        const tip = this.str(["tooltip"]); if (tip) b.title = tip;
        this.button = b;
        this.body.appendChild(b);
        this.type = this.str(["type"], "push");
        this.x = this.int(["xindex", "select_x", "x_index"], 0);
        this.y = this.int(["yindex", "select_y", "y_index"], 0);
        this.paramValue = null;
        // A push button is held between pointer down and up (wherever the pointer is let go:
        // the pointer is captured) and is never shown as "on"; a toggle shows its parameter.
        b.addEventListener("pointerdown", (e) => {
            if (e.button !== 0) return;
            b.setPointerCapture?.(e.pointerId);
            this.held = true;
            this.pressing = this.press();
        });
        const up = () => { if (this.held) { this.held = false; this.release(); } };
        b.addEventListener("pointerup", up);
        b.addEventListener("pointercancel", up);
        b.addEventListener("lostpointercapture", up);
        b.addEventListener("keydown", (e) => { if (e.key === " " || e.key === "Enter") { e.preventDefault(); this.pressing = this.press(); this.release(); } });
    }

    onValue() { return this.num(["value"], 1); }
    /** Whether the button shows its parameter's state: toggle, radio (on while the
     *  parameter has this button's value; buttons of one parameter form a group) and
     *  multi (steps through "values", showing the matching one of "labels"). */
    shows() { return ["toggle", "radio", "multi"].includes(this.type); }
    states() { return this.list(["values"], ["0", "1", "2"]).map(Number); }
    offValue() { return this.num(["valueUp", "release_value", "value_up"], 0); }
    element(value) { return Array.isArray(value) ? [this.x, this.y] : [undefined, undefined]; }

    async press() {
        if (this.button.disabled) return;
        this.button.classList.add("pressed");
        const command = this.commandTarget("command");
        if (command) await this.sendCommand(command, this.x, this.y, this.onValue());
        const param = this.path("parameter");
        if (param) {
            let v = this.onValue();
            if (this.shows()) {
                // a toggle flips the value it knows, a multi-state button steps to the next
                // of its values: pressed before the first poll, it reads the value first
                if (this.paramValue === null) this.paramValue = await this.readParameter(param);
                const cur = this.paramValue === null ? null : Number(Widget.element(this.paramValue, this.x, this.y));
                if (this.type === "toggle") v = cur === this.onValue() ? this.offValue() : this.onValue();
                if (this.type === "multi") {
                    const states = this.states();
                    v = states[(states.indexOf(cur) + 1) % states.length];
                }
            }
            const [x, y] = this.element(this.paramValue);
            if (!this.shows()) {
                await this.setParameter(param, v, x, y);
                return;
            }
            if (this.paramValue !== null) this.setParameters(new Map([[param, Widget.withElement(this.paramValue, x ?? 0, y ?? 0, v)]]));
            const a = await this.setParameter(param, v, x, y);
            if (a) this.setParameters(new Map([[param, a.value]]));
        }
    }

    async release() {
        this.button.classList.remove("pressed");
        await this.pressing;                // the release is sent after the press
        if (this.button.disabled) return;
        const up = this.commandTarget("commandUp", "release_command", "command_up");
        if (up) await this.sendCommand(up, this.x, this.y, this.offValue());
        const param = this.path("parameter");
        if (param && this.type === "push") {
            const [x, y] = this.element(this.paramValue);
            await this.setParameter(param, this.offValue(), x, y);
        }
    }

    subscriptions() { return this.enabledSubscription(); }
    parameters() { const p = this.path("parameter"); return p && this.shows() ? [p] : []; }

    setParameters(values) {
        const p = this.path("parameter");
        if (!this.shows() || !values.has(p)) return;
        this.paramValue = values.get(p);
        const cur = Number(Widget.element(this.paramValue, this.x, this.y));
        if (this.type === "multi") {
            const i = this.states().indexOf(cur);
            const labels = this.list(["labels"], []);
            this.button.textContent = (i >= 0 && labels[i]) || `${this.str(["label"], "")} ${cur}`.trim();
            this.button.dataset.state = String(cur);
            return;
        }
        const on = cur === this.onValue();
        this.button.classList.toggle("on", on);
        this.button.setAttribute("aria-pressed", on ? "true" : "false");
    }

    update(frame) { this.button.disabled = !this.enabledFrom(frame); }
}
