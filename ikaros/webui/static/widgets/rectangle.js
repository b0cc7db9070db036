// rectangle: decoration with an optional label.
// Attributes: label, background|fill|fill_color, frame_color|color, frame_width, text_color,
// font, text_align, vertical_align, padding, show_frame.
import { Widget } from "./widget.js";

export default class Rectangle extends Widget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        this.el.classList.add("rectangle");
        const fill = this.str(["fill", "fill_color"]); if (fill) this.el.style.background = fill;
        const fc = this.str(["color"]); if (fc && !attrs.frame_color) this.el.style.borderColor = fc;
        const label = document.createElement("div");
        label.className = "rectangle-label";
        label.textContent = this.str(["label"]);
        const s = label.style;
        const tc = this.str(["text_color"]); if (tc) s.color = tc;
        const font = this.str(["font"]); if (font) s.font = font;
        s.textAlign = this.str(["text_align"], "center");
        s.alignSelf = { top: "flex-start", bottom: "flex-end" }[this.str(["vertical_align"], "top")] || "center";
        const pad = this.raw(["padding"]); if (pad !== undefined) s.padding = parseFloat(pad) + "px";
        this.body.classList.add("rectangle-body");
        this.body.appendChild(label);
    }
}
