// Floating windows of the system inspector: profiling (per-module time, most time first,
// refreshed every second) and the start-up steps of the build (docs/webui.md).
import { getJSON, postJSON } from "./api.js";

const ms = (s) => (s * 1000).toFixed(3);

/** A table whose first textColumns columns are text (left) and the rest numbers (right). */
function table(headers, rows, id, textColumns = 1) {
    const t = document.createElement("table");
    t.className = "inspector-table tool-window-table";
    t.id = id;
    const head = t.createTHead().insertRow();
    for (const [i, h] of headers.entries()) {
        const th = document.createElement("th");
        th.scope = "col";
        th.textContent = h;
        if (i >= textColumns) th.className = "value";
        head.appendChild(th);
    }
    const body = t.createTBody();
    for (const r of rows) {
        const tr = body.insertRow();
        r.forEach((v, i) => { const td = tr.insertCell(); td.textContent = v; if (i >= textColumns) td.className = "value"; });
    }
    return t;
}

/** A floating window with a title bar and a close button; close() removes it. */
class ToolWindow {
    constructor(id, title, onClose) {
        this.el = document.createElement("section");
        this.el.className = "tool-window pane";
        this.el.id = id;
        this.el.setAttribute("role", "dialog");
        this.el.setAttribute("aria-label", title);
        const bar = document.createElement("div");
        bar.className = "pane-title";
        bar.textContent = title + " ";
        const close = document.createElement("button");
        close.className = "tool small";
        close.textContent = "×";
        close.title = "close";
        close.setAttribute("aria-label", "close " + title);
        close.addEventListener("click", () => this.close());
        bar.appendChild(close);
        this.body = document.createElement("div");
        this.body.className = "tool-window-body";
        this.el.append(bar, this.body);
        this.onClose = onClose;
        document.body.appendChild(this.el);
        this.el.addEventListener("keydown", (e) => { if (e.key === "Escape") { e.stopPropagation(); this.close(); } });
        close.focus();
    }

    close() {
        this.el.remove();
        this.onClose?.();
    }
}

let profilingWindow = null;

/** The profiling window: switches the measuring on while it is open. */
export async function openProfiling(notify) {
    if (profilingWindow) return profilingWindow;
    let timer = null;
    let wasOn = false;
    const w = new ToolWindow("profiling-window", "Profiling", async () => {
        clearInterval(timer);
        profilingWindow = null;
        if (!wasOn) { try { await postJSON("/api/profiling", { on: false }); } catch { } }
    });
    profilingWindow = w;
    const show = (p) => {
        const total = p.modules.reduce((a, m) => a + m.total, 0) || 1;
        const rows = p.modules.map((m) => [m.module, m.class, String(m.count), ms(m.mean), ms(m.max), ms(m.total), (100 * m.total / total).toFixed(1)]);
        w.body.replaceChildren(table(["module", "class", "ticks", "mean ms", "max ms", "total ms", "%"], rows, "profiling-table", 2));
    };
    try {
        wasOn = (await getJSON("/api/profiling")).on;
        show(await postJSON("/api/profiling", { on: true }));
    } catch (e) { notify("error", "profiling: " + e.message); }
    timer = setInterval(async () => { try { show(await getJSON("/api/profiling")); } catch { } }, 1000);
    return w;
}

/** The start-up window: the build steps of the running network and their times. */
export async function openStartup(notify) {
    document.querySelector("#startup-window")?.remove();
    const w = new ToolWindow("startup-window", "Start-up");
    try {
        const s = await getJSON("/api/startup");
        const rows = s.steps.map((x) => [x.step, ms(x.seconds)]);
        rows.push(["total", ms(s.total)]);
        w.body.replaceChildren(table(["step", "ms"], rows, "startup-table"));
    } catch (e) { notify("error", "start-up: " + e.message); }
    return w;
}
