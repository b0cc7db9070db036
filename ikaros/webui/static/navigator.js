// The navigator: the tree of groups; under each group its views and its modules.
export class Navigator {
    constructor(el, { onView, onModule }) {
        this.el = el;
        this.onView = onView;
        this.onModule = onModule;
    }

    show(network, current) {
        this.el.textContent = "";
        this.el.setAttribute("aria-label", "navigator");
        const title = document.createElement("div");
        title.className = "pane-title";
        title.textContent = "Navigator";
        this.el.appendChild(title);
        const ul = document.createElement("ul");
        ul.className = "tree";
        ul.appendChild(this.group(network.top, current, true));
        this.el.appendChild(ul);
    }

    group(g, current, open) {
        const li = document.createElement("li");
        li.className = "tree-group";
        open = open || (current && (current.group === g.path || current.group.startsWith(g.path ? g.path + "." : "")));
        // a toggle and a link side by side (a link inside a <summary> is a control inside a
        // control, which assistive technology can not reach)
        const row = document.createElement("div");
        row.className = "tree-row";
        const toggle = document.createElement("button");
        toggle.className = "tree-toggle";
        toggle.setAttribute("aria-expanded", String(Boolean(open)));
        toggle.setAttribute("aria-label", `${open ? "collapse" : "expand"} ${g.name || "(top)"}`);
        toggle.textContent = open ? "▾" : "▸";
        const name = document.createElement("a");
        name.href = "#";
        name.className = "group-name";
        name.textContent = g.name || "(top)";
        name.dataset.group = g.path;
        name.addEventListener("click", (e) => { e.preventDefault(); this.onView(g.path, 0); });
        row.append(toggle, name);
        li.appendChild(row);
        const ul = document.createElement("ul");
        (g.views || []).forEach((v, i) => {
            const item = document.createElement("li");
            item.className = "tree-view";
            const a = document.createElement("a");
            a.href = "#";
            a.textContent = v.name || `View #${i}`;
            a.dataset.group = g.path;
            a.dataset.view = String(i);
            if (current && current.group === g.path && current.view === i) a.classList.add("current");
            a.addEventListener("click", (e) => { e.preventDefault(); this.onView(g.path, i); });
            item.appendChild(a);
            ul.appendChild(item);
        });
        for (const m of g.modules || []) {
            const item = document.createElement("li");
            item.className = "tree-module";
            const a = document.createElement("a");
            a.href = "#";
            a.textContent = m.name;
            a.title = m.class;
            a.dataset.module = m.path;
            a.addEventListener("click", (e) => { e.preventDefault(); this.onModule(m.path); });
            item.appendChild(a);
            ul.appendChild(item);
        }
        for (const sub of g.groups || []) ul.appendChild(this.group(sub, current, false));
        ul.hidden = !open;
        toggle.addEventListener("click", () => {
            ul.hidden = !ul.hidden;
            toggle.setAttribute("aria-expanded", String(!ul.hidden));
            toggle.setAttribute("aria-label", `${ul.hidden ? "expand" : "collapse"} ${g.name || "(top)"}`);
            toggle.textContent = ul.hidden ? "▸" : "▾";
        });
        li.appendChild(ul);
        return li;
    }
}
