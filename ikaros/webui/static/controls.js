// Run controls: stop, pause, step, play, real time, and the tick counter.
import { api } from "./api.js";

export const STATES = ["stop", "pause", "step", "play", "realtime"];
const LABELS = { stop: "■ Stop", pause: "❚❚ Pause", step: "▶❚ Step", play: "▶ Play", realtime: "◷ Real time" };

export class Controls {
    constructor(el, { onStatus, notify }) {
        this.el = el;
        this.onStatus = onStatus;
        this.notify = notify;
        this.buttons = {};
        for (const state of STATES) {
            const b = document.createElement("button");
            b.className = "run-button";
            b.dataset.state = state;
            b.id = "run-" + state;
            b.textContent = LABELS[state];
            b.title = state;
            b.addEventListener("click", () => this.send(state));
            el.appendChild(b);
            this.buttons[state] = b;
        }
        this.tick = document.createElement("span");
        this.tick.id = "tick";
        this.tick.className = "tick-counter";
        this.tick.title = "tick";
        this.tick.textContent = "-";
        el.appendChild(this.tick);
        this.queue = Promise.resolve();
    }

    /** Requests go one at a time, in order. */
    send(state) {
        this.queue = this.queue.then(async () => {
            try {
                const status = await api.control(state);
                if (status) this.onStatus(status);
            } catch (e) {
                this.notify("error", `${state}: ${e.message}`);
            }
        });
        return this.queue;
    }

    show(status) {
        if (status.tick !== undefined) this.tick.textContent = String(status.tick);
        for (const [state, b] of Object.entries(this.buttons)) b.classList.toggle("active", status.state === state);
    }
}
