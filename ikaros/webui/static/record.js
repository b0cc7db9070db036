// The record button: records every output of the running model into an HDF5 file in the
// models folder (POST /api/record), until pressed again.
import { getJSON, postJSON } from "./api.js";

export class RecordButton {
    constructor(el, { notify }) {
        this.notify = notify;
        this.button = document.createElement("button");
        this.button.className = "run-button";
        this.button.id = "run-record";
        this.button.textContent = "● Record";
        this.button.title = "record every output into an HDF5 file in the models folder";
        this.button.addEventListener("click", () => this.toggle());
        el.appendChild(this.button);
        this.on = false;
        getJSON("/api/record").then((s) => this.show(s), () => {});
    }

    async toggle() {
        try {
            const state = await postJSON("/api/record", { on: !this.on });
            this.show(state);
            if (state.file) this.notify("print", `recording into ${state.file}`);
            else this.notify("print", "recording ended");
        } catch (e) {
            this.notify("error", `record: ${e.message}`);
        }
    }

    show(state) {
        this.on = state.recording;
        this.button.classList.toggle("active", this.on);
        this.button.textContent = this.on ? "● Recording" : "● Record";
        this.button.title = this.on ? `recording into ${state.folder}/${state.file}; press to end`
            : "record every output into an HDF5 file in the models folder";
    }
}
