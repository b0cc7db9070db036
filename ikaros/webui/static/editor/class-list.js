// The searchable class list (GET /api/classes): each class with its description, inputs,
// outputs and parameters; choosing one adds a module of that class.
import { dialog } from "../dialog.js";
import { descriptionElement, plainText } from "../describe.js";

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
        search.setAttribute("aria-label", "search classes");
        const list = h("ul", "class-list");
        list.tabIndex = 0;                      // scrolled with the keyboard too
        list.setAttribute("aria-label", "classes");
        const info = h("div", "class-info");
        info.tabIndex = 0;
        info.setAttribute("aria-label", "the class's description");
        const cols = h("div", "class-columns");
        cols.append(list, info);
        body.append(search, cols);
        let chosen = null;
        const d = dialog("Add a module", body, [
            ["Cancel", () => { d.close(); resolve(null); }],
            ["Add", () => { if (chosen) { d.close(); resolve(chosen); } }, "add-module-ok"],
        ]);
        const words = (n) => {
            const c = classes[n];
            return [n, c.description, ...(c.inputs || []).flatMap((i) => [i.name, i.description]),
                ...(c.outputs || []).flatMap((o) => [o.name, o.description]),
                ...(c.parameters || []).flatMap((p) => [p.name, p.description, ...(p.options || [])])]
                .join(" ").toLowerCase().split(/[^a-z0-9_]+/).filter(Boolean);
        };
        const index = new Map(names.map((n) => [n, { name: n.toLowerCase(), words: words(n),
            description: String(classes[n].description || "").toLowerCase().split(/[^a-z0-9_]+/).filter(Boolean) }]));
        const show = (n) => {
            chosen = n;
            list.querySelectorAll("li").forEach((li) => li.classList.toggle("current", li.dataset.class === n));
            info.textContent = "";
            const c = classes[n];
            info.append(h("div", "class-name", n), c.description ? descriptionElement("div", "class-description", c.description)
                : h("div", "class-description", "(no description)"));
            const table = (title, rows) => {
                if (!rows.length) return;
                info.append(h("div", "section-title", title));
                const t = h("table", "inspector-table");
                for (const r of rows) {
                    const tr = t.insertRow();
                    r.forEach((x, k) => {     // the last column is the description
                        const cell = tr.insertCell();
                        if (k === r.length - 1 && k > 0) cell.append(...descriptionElement("span", "", x).childNodes);
                        else cell.textContent = x;
                    });
                }
                info.append(t);
            };
            table("Inputs", (c.inputs || []).map((i) => [i.name + (i.optional ? " (optional)" : ""), i.description || ""]));
            table("Outputs", (c.outputs || []).map((o) => [o.name, o.description || ""]));
            table("Parameters", (c.parameters || []).map((p) => [p.name, p.type + (p.options ? ": " + p.options.join("/") : ""),
                p.default === null || p.default === undefined ? "" : String(p.default), p.description || ""]));
        };
        const fill = () => {
            const query = search.value.toLowerCase().trim();
            const terms = query.split(/\s+/).filter(Boolean);
            list.textContent = "";
            const found = [];
            for (const n of names) {
                const rank = classRank(index.get(n), query, terms);
                if (rank !== null) found.push([rank, n]);
            }
            found.sort((a, b) => a[0] - b[0] || a[1].localeCompare(b[1]));
            for (const [, n] of found) {
                const li = h("li", "", n);
                li.dataset.class = n;
                li.title = plainText(classes[n].description);
                li.addEventListener("click", () => show(n));
                li.addEventListener("dblclick", () => { d.close(); resolve(n); });
                list.appendChild(li);
            }
            const first = list.querySelector("li");
            if (first) show(first.dataset.class);     // the best match is the one Enter adds
            else chosen = null;
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

/** A word of the text matches a search term that begins it, or that it begins (three
 *  letters at least: "sine" finds "sin"). */
function wordMatches(words, term) {
    return words.some((w) => w.startsWith(term) || (w.length >= 3 && term.startsWith(w)));
}

/** How well a class matches: 0 its exact name, 1 a name that begins with the query, 2 a
 *  name that holds it, 3 every term in the name or description, 4 every term somewhere
 *  (ports, parameters, options); null no match. */
export function classRank(entry, query, terms) {
    if (!terms.length) return 4;
    if (entry.name === query) return 0;
    if (entry.name.startsWith(query)) return 1;
    if (entry.name.includes(query)) return 2;
    const inName = (t) => entry.name.includes(t);
    if (terms.every((t) => inName(t) || wordMatches(entry.description, t))) return 3;
    if (terms.every((t) => inName(t) || wordMatches(entry.words, t))) return 4;
    return null;
}
