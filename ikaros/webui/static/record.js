// The record button: records every output of the running model into an HDF5 file in the
// recordings folder (the user-data folder, POST /api/record), until pressed again. The
// Messages pane and the button's tooltip name the folder and the file.
import { getJSON, postJSON } from "./api.js";

export class RecordButton {
    constructor(el, { notify }) {
        this.notify = notify;
        this.button = document.createElement("button");
        this.button.className = "run-button";
        this.button.id = "run-record";
        this.button.textContent = "● Record";
        this.button.addEventListener("click", () => this.toggle());
        el.appendChild(this.button);
        this.on = false;
        this.show({ recording: false, folder: null });
        getJSON("/api/record").then((s) => this.show(s), () => {});
    }

    async toggle() {
        try {
            const state = await postJSON("/api/record", { on: !this.on });
            const ended = this.file;
            this.show(state);
            if (state.file) this.notify("print", `recording into ${this.file}`);
            else this.notify("print", ended ? `recording ended: ${ended}` : "recording ended");
        } catch (e) {
            this.notify("error", `record: ${e.message}`);
        }
    }

    show(state) {
        this.on = state.recording;
        this.file = this.on ? `${state.folder}/${state.file}` : null;
        this.button.classList.toggle("active", this.on);
        this.button.textContent = this.on ? "● Recording" : "● Record";
        this.button.title = this.on ? `recording into ${this.file}; press to end`
            : `record every output into an HDF5 file in ${state.folder ?? "the recordings folder"}`;
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
