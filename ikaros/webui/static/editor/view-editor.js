// The view editor: the widgets of one view as frames that can be selected, moved (drag) and
// resized (the corner handle), snapped to a grid of 5 to 160 px (grid − and + halve and
// double it; 10 px at first). Each frame shows its widget live, with data, as the view
// does, and the widget's own controls (sliders, buttons, menus, check boxes, a joystick's
// pad) act as in the view; the rest of the frame selects and drags. The canvas is scaled
// to fit the pane ("fit", the default) or shown at 100 % (the pane scrolls); positions stay
// in view units, and a drag of N screen pixels moves a widget by N / scale units.
// Adding, deleting and restyling go through the editor's toolbar and inspector.
import { kids, widgetBox, widgetClassOf } from "./model.js";
import { widgetClass } from "../widgets/index.js";

const GRIDS = [5, 10, 20, 40, 80, 160];     // grid spacings, px (- halves, + doubles)
const MARGIN = 20;                           // view units right of and below the widgets
/** What in a live widget is its own control: used, it acts and the frame stays put. */
const CONTROLS = "input, button, select, textarea, label, [data-control]";

export class ViewEditor {
    /** handlers: onSelect(nodes, additive), onGeometry(node, box) */
    constructor(host, handlers) {
        this.host = host;
        this.h = handlers;
        this.stage = document.createElement("div");      // the canvas's size on screen
        this.stage.className = "view-editor-stage";
        this.el = document.createElement("div");
        this.el.className = "view view-editor";
        this.stage.appendChild(this.el);
        host.appendChild(this.stage);
        this.scale = 1;
        this.fitting = localStorage.getItem("ikaros-view-fit") !== "no";
        this.drag = null;
        this.live = [];                      // the frames' widgets, with data
        this.liveToken = {};
        this.grid = GRIDS.includes(Number(localStorage.getItem("ikaros-view-grid"))) ? Number(localStorage.getItem("ikaros-view-grid")) : 10;
        this.gridBar = document.createElement("div");
        this.gridBar.className = "view-grid-bar";
        const step = (k) => {
            const b = document.createElement("button");
            b.className = "tool small";
            b.textContent = k < 0 ? "grid −" : "grid +";
            b.dataset.grid = k < 0 ? "smaller" : "larger";
            b.setAttribute("aria-label", k < 0 ? "halve the grid spacing" : "double the grid spacing");
            b.addEventListener("click", () => this.setGrid(GRIDS[Math.max(0, Math.min(GRIDS.length - 1, GRIDS.indexOf(this.grid) + k))]));
            return b;
        };
        this.gridLabel = document.createElement("span");
        this.fitButton = document.createElement("button");
        this.fitButton.className = "tool small";
        this.fitButton.dataset.zoom = "fit";
        this.fitButton.textContent = "fit";
        this.fitButton.title = "scale the view to fit the pane, or show it at 100 %";
        this.fitButton.addEventListener("click", () => this.setFitting(!this.fitting));
        this.zoomLabel = document.createElement("span");
        this.zoomLabel.className = "view-zoom";
        this.gridBar.append(step(-1), this.gridLabel, step(1), this.fitButton, this.zoomLabel);
        host.insertBefore(this.gridBar, this.stage);
        this.setGrid(this.grid);
        this.fitter = new ResizeObserver(() => this.fit());
        this.fitter.observe(host);
        this.el.addEventListener("pointerdown", (e) => this.onDown(e));
        this.move = (e) => this.onMove(e);
        this.up = (e) => this.onUp(e);
        window.addEventListener("pointermove", this.move);
        window.addEventListener("pointerup", this.up);
    }

    /** The spacing widgets snap to (and the background grid shows), remembered. */
    setGrid(px) {
        this.grid = px;
        localStorage.setItem("ikaros-view-grid", String(px));
        this.gridLabel.textContent = ` ${px} px `;
        this.el.style.backgroundSize = `${px}px ${px}px`;
    }

    snap(v) { return Math.round(v / this.grid) * this.grid; }

    /** Scale the canvas to fit the pane (on), or show it at 100 % (off), remembered. */
    setFitting(on) {
        this.fitting = on;
        localStorage.setItem("ikaros-view-fit", on ? "yes" : "no");
        this.fit();
    }

    /** Size and scale the canvas: the widgets' extent at the largest scale up to 1 that
     *  shows them whole in the pane (1 when not fitting), the canvas filling the pane. */
    fit() {
        if (!this.extent || !this.host.clientWidth) return;      // hidden: fitted when shown
        const roomW = Math.max(1, this.host.clientWidth - 1);
        const roomH = Math.max(1, this.host.clientHeight - this.gridBar.offsetHeight - 1);
        const [w, h] = this.extent;
        this.scale = this.fitting ? Math.min(1, roomW / w, roomH / h) : 1;
        const s = this.scale;
        const width = Math.max(w, Math.floor(roomW / s)), height = Math.max(h, Math.floor(roomH / s));
        Object.assign(this.el.style, { width: width + "px", height: height + "px", transform: s < 1 ? `scale(${s})` : "" });
        this.el.style.setProperty("--screen-px", `${1 / s}px`);     // handles keep their size on screen
        Object.assign(this.stage.style, { width: Math.floor(width * s) + "px", height: Math.floor(height * s) + "px" });
        this.fitButton.setAttribute("aria-pressed", String(this.fitting));
        this.fitButton.setAttribute("aria-label", this.fitting ? "show the view at 100 %" : "scale the view to fit the pane");
        this.zoomLabel.textContent = ` ${Math.round(s * 100)} % `;
        this.el.dataset.scale = String(s);
    }

    // --- live widgets: each frame shows its widget with data while the view is edited ------

    /** Build the real widget inside a frame (its controls act, see CONTROLS); the frame's
     *  text stays for a class that fails to build. */
    async makeLive(frame, body, node, cls) {
        const live = this.h.live?.();
        if (!live) return;
        const token = this.liveToken;
        const Cls = await widgetClass(cls);
        if (!Cls || token !== this.liveToken) return;
        let widget;
        try { widget = new Cls({ ...node.attrs, class: cls, show_title: "no" }, live.ctx); } catch { return; }
        widget.el.classList.add("live-widget");
        Object.assign(widget.el.style, { position: "absolute", inset: "0" });
        body.textContent = "";
        body.style.position = "relative";
        body.appendChild(widget.el);
        frame.classList.add("live");
        this.live.push(widget);
        clearTimeout(this.liveTimer);
        this.liveTimer = setTimeout(() => live.changed(), 0);    // subscribe once for all
    }

    dropLive() {
        for (const w of this.live || []) { try { w.destroy(); } catch { } }
        this.live = [];
        this.liveToken = {};
    }

    subscriptions() { return this.live.flatMap((w) => w.subscriptions()); }
    parameters() { return this.live.flatMap((w) => w.parameters()); }
    update(frame) { for (const w of this.live) { try { w.update(frame); } catch { } } }
    setParameters(values) { for (const w of this.live) { try { w.setParameters(values); } catch { } } }

    destroy() {
        this.dropLive();
        this.h.live?.().changed();
        this.fitter.disconnect();
        this.gridBar.remove();
        window.removeEventListener("pointermove", this.move);
        window.removeEventListener("pointerup", this.up);
        this.stage.remove();
    }

    show(view, selection, errors = new Map()) {
        this.view = view;
        this.dropLive();
        this.el.textContent = "";
        this.frames = new Map();
        let right = 1, bottom = 1;
        for (const w of kids(view)) {
            const box = widgetBox(w);
            right = Math.max(right, box.x + box.width + MARGIN);
            bottom = Math.max(bottom, box.y + box.height + MARGIN);
            const f = document.createElement("div");
            f.className = "widget widget-frame" + (selection.has(w) ? " selected" : "");
            const cls = widgetClassOf(w);
            f.dataset.widget = cls;
            f.dataset.title = w.attrs.title || "";
            Object.assign(f.style, { left: box.x + "px", top: box.y + "px", width: box.width + "px", height: box.height + "px" });
            const t = document.createElement("div");
            t.className = "widget-title";
            t.textContent = w.attrs.title || w.attrs.name || cls;
            const b = document.createElement("div");
            b.className = "widget-frame-body";
            b.textContent = cls + (w.attrs.source ? `\n${w.attrs.source}` : "") + (w.attrs.parameter ? `\n${w.attrs.parameter}` : "");
            if (w.attrs.color) b.style.color = w.attrs.color.split(",")[0];
            const handle = document.createElement("div");
            handle.className = "resize-handle";
            f.append(t, b, handle);
            const err = errors.get(w);
            if (err) {
                const e = document.createElement("div");
                e.className = "editor-error";
                e.textContent = err;
                f.appendChild(e);
            }
            this.el.appendChild(f);
            this.frames.set(f, w);
            this.makeLive(f, b, w, cls);
        }
        this.extent = [right, bottom];
        this.fit();
    }

    onDown(e) {
        if (e.button !== 0) return;
        const f = e.target.closest(".widget-frame");
        if (!f) { this.h.onSelect([], false); return; }
        if (e.target.closest(".live-widget") && e.target.closest(CONTROLS)) return;
        const w = this.frames.get(f);
        this.h.onSelect([w], e.shiftKey);
        const frame = [...this.frames].find(([, x]) => x === w)?.[0] || f;
        this.drag = { frame, w, resize: e.target.classList.contains("resize-handle"), cx: e.clientX, cy: e.clientY, box: widgetBox(w), moved: false };
        e.preventDefault();
    }

    onMove(e) {
        const d = this.drag;
        if (!d) return;
        const dx = (e.clientX - d.cx) / this.scale, dy = (e.clientY - d.cy) / this.scale;
        if (Math.abs(e.clientX - d.cx) + Math.abs(e.clientY - d.cy) > 2) d.moved = true;
        if (!d.moved) return;
        const b = { ...d.box };
        if (d.resize) { b.width = Math.max(40, this.snap(b.width + dx)); b.height = Math.max(30, this.snap(b.height + dy)); }
        else { b.x = Math.max(0, this.snap(b.x + dx)); b.y = Math.max(0, this.snap(b.y + dy)); }
        d.result = b;
        Object.assign(d.frame.style, { left: b.x + "px", top: b.y + "px", width: b.width + "px", height: b.height + "px" });
    }

    onUp() {
        const d = this.drag;
        this.drag = null;
        if (d && d.moved && d.result) this.h.onGeometry(d.w, d.result);
    }
}
