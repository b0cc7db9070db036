// The record button: records the outputs the user chooses (every output, or those whose
// addresses match patterns such as "Arm.*"), every n-th tick, into an HDF5 file in the
// recordings folder (the user-data folder, POST /api/record), until pressed again. Before a
// recording starts its dialog says how much data it writes (values a tick, and megabytes a
// second at the present tick rate); while it runs the button says so. The Messages pane
// and the button's tooltip name the folder and the file.
import { getJSON, postJSON } from "./api.js";
import { dialog } from "./dialog.js";

const UNITS = [["GB", 1e9], ["MB", 1e6], ["kB", 1e3]];

/** Bytes as text: "19 MB". */
export function bytesText(n) {
    for (const [unit, size] of UNITS) if (n >= size) return `${(n / size).toPrecision(2).replace(/\.0$/, "")} ${unit}`;
    return `${Math.round(n)} bytes`;
}

export class RecordButton {
    /** status(): the app's latest status (ticks_per_second, tick_duration). */
    constructor(el, { notify, status = () => ({}) }) {
        this.notify = notify;
        this.status = status;
        this.button = document.createElement("button");
        this.button.className = "run-button";
        this.button.id = "run-record";
        this.button.textContent = "● Record";
        this.button.addEventListener("click", () => (this.on ? this.stop() : this.choose()));
        el.appendChild(this.button);
        this.on = false;
        this.show({ recording: false, folder: null });
        getJSON("/api/record").then((s) => this.show(s), () => {});
    }

    /** Ticks a second: the present rate, else (paused) the model's rate in real time. */
    rate() {
        const s = this.status() || {};
        if (s.ticks_per_second > 0) return [s.ticks_per_second, "at the present rate"];
        if (s.tick_duration > 0) return [1 / s.tick_duration, "in real time"];
        return [0, ""];
    }

    /** What a recording of ``state`` (values a tick) writes: a sentence. */
    amount(state, every = 1) {
        const perTick = 4 * state.values;
        const [tps, how] = this.rate();
        const perSecond = tps > 0 ? `, about ${bytesText(perTick * tps / every)} a second ${how} (${Math.round(tps)} ticks a second)` : "";
        return `${state.outputs} output${state.outputs === 1 ? "" : "s"}, ${state.values} values: ` +
            `${bytesText(perTick)} a recorded tick${perSecond}, before compression`;
    }

    /** The dialog that chooses what to record and says how much it writes. */
    choose() {
        const body = document.createElement("div");
        const field = (label, input) => {
            const l = document.createElement("label");
            l.className = "dialog-field";
            l.append(label + " ", input);
            body.appendChild(l);
            return input;
        };
        const only = field("Outputs", Object.assign(document.createElement("input"), {
            id: "record-only", placeholder: "every output, or patterns: Arm.*, Gain.OUTPUT" }));
        const every = field("Every", Object.assign(document.createElement("input"), {
            id: "record-every", type: "number", min: "1", value: "1" }));
        every.after(" ticks");
        const note = document.createElement("div");
        note.className = "dialog-note";
        note.id = "record-amount";
        body.appendChild(note);
        let asked = 0;
        const estimate = async () => {
            const n = ++asked;
            const q = only.value.trim() ? `?only=${encodeURIComponent(only.value.trim())}` : "";
            try {
                const s = await getJSON("/api/record" + q);
                if (n !== asked) return;
                const big = (s.largest || []).filter(([, v]) => v > 0.2 * s.values).map(([p, v]) => `${p} (${v} values)`);
                note.textContent = this.amount(s, Math.max(1, Number(every.value) || 1)) + "." +
                    (big.length ? ` Most of it: ${big.join(", ")}.` : "");
                note.classList.remove("error");
            } catch (e) {
                if (n !== asked) return;
                note.textContent = e.message;
                note.classList.add("error");
            }
        };
        const start = async () => {
            const patterns = only.value.split(",").map((p) => p.trim()).filter(Boolean);
            const request = { on: true, every: Math.max(1, Math.round(Number(every.value) || 1)) };
            if (patterns.length) request.only = patterns;
            try {
                const state = await postJSON("/api/record", request);
                d.close();
                this.show(state);
                this.notify("print", `recording into ${this.file}: ${this.amount(state, state.every)}`);
            } catch (e) {
                note.textContent = e.message;
                note.classList.add("error");
            }
        };
        const d = dialog("Record", body, [["Cancel", () => d.close()], ["Record", start, "record-start"]]);
        only.addEventListener("input", estimate);
        every.addEventListener("input", estimate);
        for (const input of [only, every]) {
            input.addEventListener("keydown", (e) => {
                if (e.key === "Enter") start();
                if (e.key === "Escape") d.close();
            });
        }
        estimate();
        only.focus();
    }

    async stop() {
        try {
            const ended = this.file;
            this.show(await postJSON("/api/record", { on: false }));
            this.notify("print", ended ? `recording ended: ${ended}` : "recording ended");
        } catch (e) {
            this.notify("error", `record: ${e.message}`);
        }
    }

    show(state) {
        this.state = state;
        this.on = state.recording;
        this.file = this.on ? `${state.folder}/${state.file}` : null;
        this.button.classList.toggle("active", this.on);
        this.button.textContent = this.on ? "● Recording" : "● Record";
        this.button.title = this.on ? `recording into ${this.file} (${this.amount(state, state.every)}); press to end`
            : `choose outputs to record into an HDF5 file in ${state.folder ?? "the recordings folder"}`;
        if (this.on) this.showRate(state);
    }

    /** A new status: the rate while recording follows the tick rate. */
    statusChanged() { if (this.on) this.showRate(this.state); }

    /** While recording, the button says how much it writes a second. */
    showRate(state) {
        const [tps] = this.rate();
        if (tps > 0) this.button.textContent = `● Recording ${bytesText(4 * state.values * tps / (state.every || 1))}/s`;
    }
}

/** The replay bar of `ikaros --replay run.h5`: a slider over the recorded rows; moving it
 * shows that row (POST /api/replay); while the model plays, it follows the rows shown. */
export class ReplayBar {
    constructor(el, { notify, recordButton }) {
        this.notify = notify;
        this.el = el;
        this.recordButton = recordButton;
        getJSON("/api/replay").then((s) => { if (s.replay) this.build(s); }, () => {});
    }

    build(state) {
        this.recordButton?.button.remove();          // a replay is not recorded again
        this.slider = document.createElement("input");
        this.slider.type = "range";
        this.slider.id = "replay-slider";
        this.slider.min = "0";
        this.slider.max = String(state.rows - 1);
        this.slider.title = `replaying ${state.file}`;
        this.label = document.createElement("span");
        this.label.id = "replay-tick";
        this.label.style.whiteSpace = "nowrap";
        this.label.style.fontVariantNumeric = "tabular-nums";
        this.el.append(this.slider, this.label);
        this.pending = null;
        this.busy = false;
        this.slider.addEventListener("input", () => this.seek(Number(this.slider.value)));
        this.show(state);
        setInterval(() => { if (!this.busy) getJSON("/api/replay").then((s) => this.show(s), () => {}); }, 500);
    }

    /** One request at a time; the latest position wins. */
    async seek(row) {
        this.pending = row;
        if (this.busy) return;
        this.busy = true;
        try {
            while (this.pending !== null) {
                const next = this.pending;
                this.pending = null;
                this.show(await postJSON("/api/replay", { row: next }));
            }
        } catch (e) {
            this.notify("error", `replay: ${e.message}`);
        } finally {
            this.busy = false;
        }
    }

    show(state) {
        if (!state.replay) return;
        if (state.row >= 0 && this.pending === null) this.slider.value = String(state.row);
        this.label.textContent = state.tick === null ? `row -/${state.rows}`
            : `recorded tick ${state.tick} (row ${state.row + 1}/${state.rows})`;
    }
}
