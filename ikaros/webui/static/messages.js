// The messages pane: the kernel's notifications as they happen.
const LEVELS = { 1: "exception", 2: "end_of_file", 3: "terminate", 4: "fatal_error", 5: "warning", 6: "print", 7: "debug", 8: "trace" };
const MAX = 1000;

export class Messages {
    constructor(el) {
        this.el = el;
        this.list = el.querySelector(".message-list");
        this.seen = new Set();
    }

    add(messages) {
        const atBottom = this.list.scrollTop + this.list.clientHeight >= this.list.scrollHeight - 4;
        for (const m of messages) {
            if (m.seq !== undefined) {
                if (this.seen.has(m.seq)) continue;
                this.seen.add(m.seq);
            }
            const level = typeof m.level === "number" ? LEVELS[m.level] || String(m.level) : String(m.level || "print");
            const row = document.createElement("div");
            row.className = "message level-" + level;
            const parts = [
                ["message-tick", m.tick !== undefined && m.tick !== null ? String(m.tick) : ""],
                ["message-level", level.replace(/_/g, " ")],
                ["message-module", m.module || ""],
                ["message-text", m.message || ""],
            ];
            for (const [cls, text] of parts) {
                const span = document.createElement("span");
                span.className = cls;
                span.textContent = text;
                row.appendChild(span);
            }
            this.list.appendChild(row);
        }
        while (this.list.children.length > MAX) this.list.firstChild.remove();
        if (atBottom) this.list.scrollTop = this.list.scrollHeight;
    }

    /** A message from the UI itself. */
    local(level, message) { this.add([{ level, module: "web UI", message }]); }

    clear() { this.list.textContent = ""; }
}
