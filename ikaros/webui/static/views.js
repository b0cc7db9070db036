// A view: widgets placed at (x, y) with width x height as the model file says.
import { widgetClass } from "./widgets/index.js";

const MIN_ZOOM = 0.6;

export class ViewRenderer {
    /**
     * @param container element to draw into
     * @param view {name, widgets: [attrs...]}
     * @param ctx {groupPath, selectModule, notify, shapeOf}
     */
    constructor(container, view, ctx) {
        this.container = container;
        this.view = view;
        this.ctx = ctx;
        this.widgets = [];
        this.el = document.createElement("div");
        this.el.className = "view";
        this.el.dataset.view = view.name || "";
        container.appendChild(this.el);
    }

    async build() {
        let right = 0, bottom = 0;
        const placed = [];
        for (const attrs of this.view.widgets || []) {
            const x = parseFloat(attrs.x ?? attrs._x) || 0, y = parseFloat(attrs.y ?? attrs._y) || 0;
            const w = parseFloat(attrs.width) || 200, h = parseFloat(attrs.height) || 200;
            // A widget drawn over an earlier one is see-through (as in the original), so
            // layered widgets (a path under markers) all show.
            const overlay = placed.some((r) => x < r.x + r.w && r.x < x + w && y < r.y + r.h && r.y < y + h);
            placed.push({ x, y, w, h });
            right = Math.max(right, x + w);
            bottom = Math.max(bottom, y + h);
            let widget;
            const Cls = await widgetClass(attrs.class);
            try {
                if (!Cls) throw new Error(`unknown widget "${attrs.class}"`);
                widget = new Cls(attrs, this.ctx);
            } catch (e) {
                widget = { el: document.createElement("div"), subscriptions: () => [], parameters: () => [], update() { }, setParameters() { }, destroy() { } };
                widget.el.className = "widget widget-error";
                widget.el.textContent = e.message;
                this.ctx.notify?.("warning", `${attrs.class}: ${e.message}`);
            }
            Object.assign(widget.el.style, { left: x + "px", top: y + "px", width: w + "px", height: h + "px" });
            if (overlay) widget.el.classList.add("see-through");
            this.el.appendChild(widget.el);
            this.widgets.push(widget);
        }
        this.el.style.width = right + 20 + "px";
        this.el.style.height = bottom + 20 + "px";
        this.naturalWidth = right + 20;
        this.fitter = new ResizeObserver(() => this.fit());
        this.fitter.observe(this.container);
        this.fit();
        return this;
    }

    /** A view wider than its pane is scaled down to fit it (to MIN_ZOOM at most; beyond
     *  that the pane scrolls), so that no widget is cut off. */
    fit() {
        const room = this.container.clientWidth;
        if (!room || !this.naturalWidth) return;
        const zoom = Math.max(MIN_ZOOM, Math.min(1, room / this.naturalWidth));
        this.el.style.zoom = zoom < 1 ? String(zoom) : "";
    }

    subscriptions() { return this.widgets.flatMap((w) => w.subscriptions()); }
    parameters() { return this.widgets.flatMap((w) => w.parameters()); }

    update(frame) {
        for (const w of this.widgets) {
            try { w.update(frame); } catch (e) { console.error(e); }
        }
    }

    setParameters(values) {
        for (const w of this.widgets) {
            try { w.setParameters(values); } catch (e) { console.error(e); }
        }
    }

    destroy() {
        this.fitter?.disconnect();
        for (const w of this.widgets) { try { w.destroy(); } catch { } }
        this.el.remove();
    }
}
