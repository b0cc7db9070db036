// The searchable class list (GET /api/classes): each class with its description, inputs,
// outputs and parameters; choosing one adds a module of that class.
import { dialog } from "./files.js";

function h(tag, cls, text) {
    const e = document.createElement(tag);
    if (cls) e.className = cls;
    if (text !== undefined) e.textContent = text;
    return e;
}

/** Show the class list; resolves to a class name, or null when cancelled. */
export function pickClass(classes) {
    return new Promise((resolve) => {
        const names = Object.keys(classes).sort((a, b) => a.localeCompare(b));
        const body = h("div", "class-picker");
        const search = h("input", "class-search");
        search.type = "search";
        search.placeholder = "search classes (name, description, inputs, outputs)";
        const list = h("ul", "class-list");
        const info = h("div", "class-info");
        const cols = h("div", "class-columns");
        cols.append(list, info);
        body.append(search, cols);
        let chosen = null;
        const d = dialog("Add a module", body, [
            ["Cancel", () => { d.close(); resolve(null); }],
            ["Add", () => { if (chosen) { d.close(); resolve(chosen); } }, "add-module-ok"],
        ]);
        const text = (n) => {
            const c = classes[n];
            return [n, c.description, ...(c.inputs || []).map((i) => i.name), ...(c.outputs || []).map((o) => o.name),
                ...(c.parameters || []).map((p) => p.name)].join(" ").toLowerCase();
        };
        const show = (n) => {
            chosen = n;
            list.querySelectorAll("li").forEach((li) => li.classList.toggle("current", li.dataset.class === n));
            info.textContent = "";
            const c = classes[n];
            info.append(h("div", "class-name", n), h("div", "class-description", c.description || "(no description)"));
            const table = (title, rows) => {
                if (!rows.length) return;
                info.append(h("div", "section-title", title));
                const t = h("table", "inspector-table");
                for (const r of rows) {
                    const tr = t.insertRow();
                    r.forEach((x) => { tr.insertCell().textContent = x; });
                }
                info.append(t);
            };
            table("Inputs", (c.inputs || []).map((i) => [i.name + (i.optional ? " (optional)" : ""), i.description || ""]));
            table("Outputs", (c.outputs || []).map((o) => [o.name, o.description || ""]));
            table("Parameters", (c.parameters || []).map((p) => [p.name, p.type + (p.options ? ": " + p.options.join("/") : ""),
                p.default === null || p.default === undefined ? "" : String(p.default), p.description || ""]));
        };
        const fill = () => {
            const words = search.value.toLowerCase().split(/\s+/).filter(Boolean);
            list.textContent = "";
            for (const n of names) {
                const t = text(n);
                if (!words.every((w) => t.includes(w))) continue;
                const li = h("li", "", n);
                li.dataset.class = n;
                li.title = classes[n].description || "";
                li.addEventListener("click", () => show(n));
                li.addEventListener("dblclick", () => { d.close(); resolve(n); });
                list.appendChild(li);
            }
            const first = list.querySelector("li");
            if (first && !list.querySelector(`li[data-class="${CSS.escape(chosen || "")}"]`)) show(first.dataset.class);
        };
        search.addEventListener("input", fill);
        search.addEventListener("keydown", (e) => {
            if (e.key === "Enter" && chosen) { d.close(); resolve(chosen); }
            if (e.key === "Escape") { d.close(); resolve(null); }
        });
        fill();
        search.focus();
    });
}
