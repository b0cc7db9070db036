// Resizable panes: a splitter on the navigator's right edge, one on the inspector's left edge
// and one above the messages. Drag one, or focus it and press the arrow keys (Home resets
// the size); the sizes are CSS custom properties on <html>, remembered by the browser.
const KEY = "ikaros-panes";
const PANES = [
    // [id, custom property, default px, min, max, axis, sign: +1 grows with the pointer]
    ["split-navigator", "--nav-width", 220, 120, 600, "x", +1, "#navigator", "resize the navigator"],
    ["split-inspector", "--inspector-width", 300, 200, 700, "x", -1, "#inspector", "resize the inspector"],
    ["split-messages", "--messages-height", 140, 60, 600, "y", -1, "#messages", "resize the messages"],
];

// the toolbar buttons that show or hide a pane: [id, body class when hidden, name]
const TOGGLES = [["toggle-nav", "hide-nav", "navigator"], ["toggle-system", "hide-system", "System"],
    ["toggle-messages", "hide-messages", "Messages"]];

export class Panes {
    constructor() {
        let saved = {};
        try { saved = JSON.parse(localStorage.getItem(KEY) || "{}"); } catch { saved = {}; }
        this.sizes = {};
        this.splitters = [];
        for (const [id, prop, def, min, max, axis, sign, pane, label] of PANES) {
            const size = Number.isFinite(saved[prop]) ? saved[prop] : def;
            const s = document.createElement("div");
            s.id = id;
            s.className = `splitter splitter-${axis}`;
            s.tabIndex = 0;
            s.setAttribute("role", "separator");
            s.setAttribute("aria-orientation", axis === "x" ? "vertical" : "horizontal");
            s.setAttribute("aria-label", label);
            s.setAttribute("aria-valuemin", String(min));
            s.setAttribute("aria-valuemax", String(max));
            s.title = label + " (drag, or arrow keys)";
            const spec = { s, prop, def, min, max, axis, sign, pane };
            this.set(spec, size);
            s.addEventListener("pointerdown", (e) => this.drag(spec, e));
            s.addEventListener("keydown", (e) => this.key(spec, e));
            document.body.appendChild(s);
            this.splitters.push(spec);
        }
        this.place();
        window.addEventListener("resize", () => this.place());
        new MutationObserver(() => this.place()).observe(document.body, { attributes: true, attributeFilter: ["class"] });
    }

    set(spec, px) {
        const v = Math.round(Math.min(spec.max, Math.max(spec.min, px)));
        this.sizes[spec.prop] = v;
        document.documentElement.style.setProperty(spec.prop, v + "px");
        spec.s.setAttribute("aria-valuenow", String(v));
        localStorage.setItem(KEY, JSON.stringify(this.sizes));
        this.place();
    }

    /** Put each splitter on the edge of its pane (hidden with a hidden pane), and say on
     *  the toolbar's toggles whether their pane is shown. */
    place() {
        for (const [id, hidden, name] of TOGGLES) {
            const b = document.getElementById(id);
            if (!b) continue;
            b.setAttribute("aria-pressed", String(!document.body.classList.contains(hidden)));
            if (!b.hasAttribute("aria-label")) b.setAttribute("aria-label", name);
        }
        for (const { s, axis, pane, sign } of this.splitters || []) {
            const el = document.querySelector(pane);
            const r = el?.getBoundingClientRect();
            const shown = r && r.width > 0 && r.height > 0 && getComputedStyle(el).display !== "none";
            s.hidden = !shown;
            if (!shown) continue;
            if (axis === "x") {
                s.style.left = (sign > 0 ? r.right : r.left) - 3 + "px";
                s.style.top = r.top + "px";
                s.style.height = r.height + "px";
            } else {
                s.style.top = r.top - 3 + "px";
                s.style.left = r.left + "px";
                s.style.width = r.width + "px";
            }
        }
    }

    drag(spec, e) {
        e.preventDefault();
        const start = spec.axis === "x" ? e.clientX : e.clientY;
        const from = this.sizes[spec.prop];
        spec.s.setPointerCapture(e.pointerId);
        const move = (m) => {
            const at = spec.axis === "x" ? m.clientX : m.clientY;
            this.set(spec, from + spec.sign * (at - start));
        };
        const up = () => {
            spec.s.removeEventListener("pointermove", move);
            spec.s.removeEventListener("pointerup", up);
            window.dispatchEvent(new Event("resize"));       // views and the editor fit again
        };
        spec.s.addEventListener("pointermove", move);
        spec.s.addEventListener("pointerup", up);
    }

    key(spec, e) {
        const grow = spec.axis === "x" ? { ArrowRight: 1, ArrowLeft: -1 } : { ArrowUp: 1, ArrowDown: -1 };
        let d = grow[e.key];
        if (e.key === "Home") { this.set(spec, spec.def); e.preventDefault(); return; }
        if (!d) return;
        if (spec.axis === "x") d *= spec.sign;
        e.preventDefault();
        this.set(spec, this.sizes[spec.prop] + d * (e.shiftKey ? 50 : 10));
    }
}
