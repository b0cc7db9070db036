// Model files: save, save as a new .ikg, a new model, open another model from the folder
// (POST /api/save, /api/new, /api/open; GET /api/files), and the editor's small dialogs.
import { ApiError, getJSON } from "../api.js";
import { dialog } from "../dialog.js";

const TOKEN = new URLSearchParams(location.search).get("token");

/** POST JSON; a failure is an ApiError that keeps the answer's body (node, path). */
async function post(url, body) {
    const headers = { "Content-Type": "application/json" };
    if (TOKEN) headers.Authorization = "Bearer " + TOKEN;
    const r = await fetch(url, { method: "POST", headers, body: JSON.stringify(body) });
    let answer = null;
    try { answer = await r.json(); } catch { answer = null; }
    if (!r.ok) {
        const e = new ApiError(r.status, answer?.error || `${r.status} ${r.statusText}`);
        e.body = answer || {};
        throw e;
    }
    return answer;
}

/** Ask for one line of text; resolves to the text or null. */
export function ask(title, label, value = "", id = "dialog-input") {
    return new Promise((resolve) => {
        const body = document.createElement("label");
        body.className = "dialog-field";
        body.textContent = label + " ";
        const input = document.createElement("input");
        input.id = id;
        input.value = value;
        body.appendChild(input);
        const ok = () => { d.close(); resolve(input.value.trim()); };
        const d = dialog(title, body, [["Cancel", () => { d.close(); resolve(null); }], ["OK", ok, "dialog-ok"]]);
        input.addEventListener("keydown", (e) => {
            if (e.key === "Enter") ok();
            if (e.key === "Escape") { d.close(); resolve(null); }
        });
        input.focus();
        input.select();
    });
}

export const files = {
    model: () => getJSON("/api/model"),
    list: () => getJSON("/api/files"),
    /** version: the file's version the edits began from (undefined: overwrite as is). */
    save: (tree, filename, version) => post("/api/save", {
        tree, ...(filename ? { filename } : {}), ...(version !== undefined ? { version } : {}),
    }),
    apply: (tree, state) => post("/api/apply", state ? { tree, state } : { tree }),
    open: (filename) => post("/api/open", { filename }),
    newModel: (name) => post("/api/new", { name }),
};

/** Pick a model from the folder; resolves to a file name or null. */
export async function pickFile(notify) {
    let answer;
    try { answer = await files.list(); } catch (e) { notify("error", "files: " + e.message); return null; }
    return new Promise((resolve) => {
        const body = document.createElement("div");
        const where = document.createElement("div");
        where.className = "dialog-note";
        where.textContent = answer.folder || "";
        const list = document.createElement("ul");
        list.className = "file-list";
        let chosen = null;
        for (const f of answer.files || []) {
            const li = document.createElement("li");
            li.textContent = f;
            li.dataset.file = f;
            li.addEventListener("click", () => {
                chosen = f;
                list.querySelectorAll("li").forEach((x) => x.classList.toggle("current", x === li));
            });
            li.addEventListener("dblclick", () => { d.close(); resolve(f); });
            list.appendChild(li);
        }
        body.append(where, list);
        const d = dialog("Open a model", body, [
            ["Cancel", () => { d.close(); resolve(null); }],
            ["Open", () => { if (chosen) { d.close(); resolve(chosen); } }, "open-ok"],
        ]);
    });
}
