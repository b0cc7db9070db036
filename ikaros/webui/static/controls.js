// Run controls: stop, pause, step, play, fast-forward, real time; the run state as text; the
// tick counter ("n / N" with a progress bar when a stop tick is set); the model's state
// (save, load, reset) and quit.
import { api, postJSON } from "./api.js";
import { ask } from "./editor/files.js";

export const STATES = ["stop", "pause", "step", "play", "fastforward", "realtime"];
const ICONS = { stop: "■", pause: "❚❚", step: "▶❚", play: "▶", fastforward: "▶▶", realtime: "◷" };
const LABELS = { stop: "Stop", pause: "Pause", step: "Step", play: "Play", fastforward: "Fast", realtime: "Real time" };
const TITLES = {
    stop: "stop the run loop", pause: "pause after the current tick", step: "run one tick",
    play: "run as fast as possible", fastforward: "run as fast as possible, showing data only ten times a second",
    realtime: "run one tick per tick duration",
};
// the run state in words (shown beside the buttons, not by colour alone)
export const STATE_TEXT = { stop: "stopped", pause: "paused", step: "stepping", play: "playing", fastforward: "fast-forward", realtime: "real time" };

function button(parent, id, text, title, fn, icon = "") {
    const b = document.createElement("button");
    b.id = id;
    b.className = "run-button";
    if (icon) {
        // the word hides in a narrow window; the icon and the name stay
        const i = document.createElement("span");
        i.setAttribute("aria-hidden", "true");
        i.textContent = icon;
        const w = document.createElement("span");
        w.className = "run-label";
        w.textContent = " " + text;
        b.append(i, w);
        b.setAttribute("aria-label", text);
    } else {
        b.textContent = text;
    }
    b.title = title;
    b.addEventListener("click", fn);
    parent.appendChild(b);
    return b;
}

export class Controls {
    /** scope(): the path of the one module or group selected in the editor, or null. */
    constructor(el, { onStatus, notify, scope = () => null }) {
        this.el = el;
        this.onStatus = onStatus;
        this.notify = notify;
        this.scope = scope;
        this.buttons = {};
        el.setAttribute("role", "group");
        el.setAttribute("aria-label", "run controls");
        for (const state of STATES) {
            const b = button(el, "run-" + state, LABELS[state], TITLES[state], () => this.send(state), ICONS[state]);
            b.dataset.state = state;
            b.setAttribute("aria-pressed", "false");
            this.buttons[state] = b;
        }
        this.stateText = document.createElement("span");
        this.stateText.id = "run-state";
        this.stateText.className = "run-state";
        this.stateText.setAttribute("role", "status");
        this.stateText.setAttribute("aria-label", "run state");
        el.appendChild(this.stateText);
        this.tick = document.createElement("span");
        this.tick.id = "tick";
        this.tick.className = "tick-counter";
        this.tick.title = "tick";
        this.tick.setAttribute("aria-label", "tick");
        this.tick.textContent = "-";
        el.appendChild(this.tick);
        this.progress = document.createElement("progress");
        this.progress.id = "tick-progress";
        this.progress.className = "tick-progress";
        this.progress.max = 1;
        this.progress.value = 0;
        this.progress.hidden = true;
        this.progress.setAttribute("aria-label", "progress to the stop tick");
        el.appendChild(this.progress);
        this.buildStateMenu(el);
        this.queue = Promise.resolve();
    }

    buildStateMenu(el) {
        const menu = document.createElement("details");
        menu.className = "tool-menu";
        menu.id = "state-menu";
        const summary = document.createElement("summary");
        summary.className = "tool";
        summary.textContent = "State ▾";
        summary.title = "save, load or reset the model's state; quit";
        summary.setAttribute("aria-label", "model state and quit");
        menu.appendChild(summary);
        const list = document.createElement("div");
        list.className = "tool-menu-list";
        menu.appendChild(list);
        const item = (id, text, title, fn) => {
            const b = button(list, id, text, title, async () => { menu.open = false; await fn(); });
            b.className = "tool small";
            return b;
        };
        this.stateItems = {
            save: item("state-save", "Save state…", "", () => this.saveState()),
            load: item("state-load", "Load state…", "", () => this.loadState()),
            reset: item("state-reset", "Reset state", "", () => this.state({ action: "reset" })),
        };
        item("quit", "Quit", "stop the run and end ikaros", () => this.quit());
        this.labelStateItems();
        // the items say what they act on: the model, or the module or group selected
        summary.addEventListener("click", () => this.labelStateItems());
        el.appendChild(menu);
    }

    labelStateItems() {
        const scope = this.scope();
        const { save, load, reset } = this.stateItems;
        if (scope) {
            save.textContent = `Save state of ${scope}…`;
            save.title = `save the outputs and state of ${scope} to a file`;
            load.textContent = `Load state into ${scope}…`;
            load.title = `load a state saved from ${scope} (or from another module of its class)`;
            reset.textContent = `Reset state of ${scope}`;
            reset.title = `${scope} back to its state after init; the tick stays`;
        } else {
            save.textContent = "Save state…";
            save.title = "save every module's outputs and state, and the tick, to a file";
            load.textContent = "Load state…";
            load.title = "load a saved state";
            reset.textContent = "Reset state";
            reset.title = "every module back to its state after init, tick 0";
        }
    }

    /** model.state, or model.A.B.state for the state of the selected A.B. */
    defaultStateFile() {
        const file = document.querySelector("#file-name")?.textContent.replace(/ •$/, "") || "model.ikg";
        const scope = this.scope();
        return file.replace(/\.ikg$/, "") + (scope ? "." + scope : "") + ".state";
    }

    async saveState() {
        const name = await ask("Save state", "State file (in the models folder)", this.defaultStateFile(), "state-file");
        if (name) await this.state({ action: "save", filename: name.endsWith(".state") ? name : name + ".state" });
    }

    async loadState() {
        const name = await ask("Load state", "State file (in the models folder)", this.defaultStateFile(), "state-file");
        if (name) await this.state({ action: "load", filename: name.endsWith(".state") ? name : name + ".state" });
    }

    /** POST /api/state, scoped to the module or group selected in the editor. */
    async state(body) {
        const scope = this.scope();
        if (scope) body.scope = scope;
        try {
            const a = await postJSON("/api/state", body);
            const what = a.scope === "network" ? "the model's state" : `the state of ${a.scope}`;
            const done = { save: `saved ${what} to ${a.file}`, load: `loaded ${what} from ${a.file}`, reset: `reset ${what}` }[a.action];
            this.notify("info", `${done} (tick ${a.tick})`);
            this.onStatus(await api.status());
        } catch (e) {
            this.notify("error", `state ${body.action}: ${e.message}`);
        }
    }

    async quit() {
        if (!confirm("Quit ikaros? The run stops and the server ends.")) return;
        try {
            await postJSON("/api/quit", {});
            document.body.dataset.quit = "yes";
            const overlay = document.querySelector("#overlay");
            overlay.hidden = false;
            overlay.textContent = "ikaros has quit: close this tab.";
        } catch (e) {
            this.notify("error", "quit: " + e.message);
        }
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
        const stop = status.stop_tick;
        const counting = typeof stop === "number" && stop > 0;
        if (status.tick !== undefined) this.tick.textContent = counting ? `${status.tick} / ${stop}` : String(status.tick);
        this.progress.hidden = !counting;
        if (counting) {
            this.progress.value = Math.min(1, status.tick / stop);
            this.progress.title = `${Math.round(100 * this.progress.value)} % of ${stop} ticks`;
        }
        this.stateText.textContent = STATE_TEXT[status.state] || status.state || "";
        for (const [state, b] of Object.entries(this.buttons)) {
            const on = status.state === state;
            b.classList.toggle("active", on);
            b.setAttribute("aria-pressed", String(on));
        }
    }
}
