// text: static text, the value of a (string) parameter, or strings chosen by a source.
// Attributes: text (static), parameter (shows its value), select_source + strings (shows
// the strings whose element in the source's first row is > 0, joined by separator), prefix,
// postfix, separator, decimals, text_color, font, text_align, padding, placeholder.
import { Widget, formatNumber } from "./widget.js";

export default class Text extends Widget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        this.span = document.createElement("div");
        this.span.className = "text-content";
        const s = this.span.style;
        const color = this.str(["text_color"]); if (color) s.color = color;
        const font = this.str(["font"]); if (font) s.font = font;
        s.textAlign = this.str(["text_align", "textAlign"], "left");
        const pad = this.raw(["padding"]); if (pad !== undefined) s.padding = parseFloat(pad) + "px";
        this.body.appendChild(this.span);
        this.show(this.str(["text"], this.str(["placeholder"], "")), !this.attrs.text);
    }

    show(text, raw = false) {
        this.value = text;
        this.span.textContent = raw ? text : this.str(["prefix"]) + text + this.str(["postfix", "suffix"]);
    }

    subscriptions() {
        const p = this.path("select_source", "select");
        return p && this.attrs.strings !== undefined ? [{ path: p, format: "raw" }] : [];
    }

    parameters() { const p = this.path("parameter"); return p ? [p] : []; }

    setParameters(values) {
        const p = this.path("parameter");
        if (!values.has(p)) return;
        let v = values.get(p);
        const d = this.int(["decimals"], -1);
        if (Array.isArray(v)) v = v.flat(Infinity).map((x) => formatNumber(x, d)).join(this.str(["separator"], ", "));
        else if (typeof v === "number") v = formatNumber(v, d);
        this.show(String(v));
    }

    update(frame) {
        const p = this.path("select_source", "select");
        if (!p || this.attrs.strings === undefined) return;
        const item = frame.get(p);
        if (!item) return;
        const strings = this.list(["strings"], []);
        const cols = item.shape.length ? item.shape[item.shape.length - 1] : 1;
        const chosen = [];
        for (let i = 0; i < Math.min(cols, strings.length); i++) if (item.data[i] > 0) chosen.push(strings[i]);
        this.show(chosen.join(this.str(["separator"], ", ")));
    }
}
