// image: an image from an output, or from files beside the model (/files/).
// Attributes: source (an array (rows, cols) with values 0..1, or (3, rows, cols) for rgb; the
// Ikaros 2 form "M.R+G+B" joins three outputs), format (gray/fire/spectrum/red/green/blue/
// rgb), file (a comma list of file names) with index|index_source selecting one, scale
// (none/width/height/both), opacity, flips, and a click command: command (a command path)
// or module + command (Ikaros 2); x and y are sent as fractions 0..1.
import { fileURL } from "../api.js";
import { CanvasWidget, colorTable, resolvePath } from "./widget.js";

const BIG = 65536;   // above this many elements gray/rgb images come as JPEG

export default class Image_ extends CanvasWidget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        this.format = this.str(["format"], "gray");
        this.files = this.list(["file"], []);
        this.bitmap = null;      // canvas or ImageBitmap or <img>
        this.fileIndex = -1;
        const o = this.num(["opacity"], 1);
        this.canvas.style.opacity = o;
        this.canvas.addEventListener("click", (e) => this.click(e));
        if (this.commandTarget("command")) this.canvas.dataset.control = "";   // also in the view editor
        if (this.files.length) this.showFile(0);
    }

    sources() {
        const src = this.attrs.source || "";
        if (src.includes("+")) {
            // Ikaros 2: "M.R+G+B" -> M.R, M.G, M.B
            const dot = src.lastIndexOf(".", src.indexOf("+"));
            const prefix = dot >= 0 ? src.slice(0, dot + 1) : "";
            const names = (dot >= 0 ? src.slice(dot + 1) : src).split("+");
            return names.map((n) => resolvePath(this.groupPath, prefix + n));
        }
        const p = this.path("source");
        return p ? [p] : [];
    }

    wire(path) {
        if (this.format !== "gray" && this.format !== "rgb") return "raw";
        const shape = this.ctx.shapeOf ? this.ctx.shapeOf(path) : null;
        const n = shape ? shape.reduce((a, b) => a * b, 1) : 0;
        return n > BIG ? "jpeg" : "raw";
    }

    subscriptions() {
        const subs = this.sources().map((p) => ({ path: p, format: this.wire(p) }));
        const idx = this.path("index_source", "index");
        if (idx && this.files.length) subs.push({ path: idx, format: "raw" });
        return subs;
    }

    showFile(i) {
        if (i === this.fileIndex || i < 0 || i >= this.files.length) return;
        this.fileIndex = i;
        const img = new window.Image();
        img.onload = () => { this.bitmap = img; this.draw(); };
        const urls = this.attrs.file_url ? String(this.attrs.file_url).split(",") : null;
        img.src = urls && urls[i] ? urls[i] : fileURL(this.files[i]);
        this.imgEl = img;
    }

    async update(frame) {
        if (this.files.length) {
            const idx = this.path("index_source", "index");
            const item = idx ? frame.get(idx) : null;
            if (item && item.data.length) this.showFile(Math.round(item.data[0]));
        }
        const paths = this.sources();
        if (!paths.length) return;
        const items = paths.map((p) => frame.get(p, this.wire(p)) || frame.get(p));
        if (items.some((i) => !i)) return;
        if (items[0].data instanceof Blob) {
            const bmp = await createImageBitmap(items[0].data);
            this.bitmap = bmp;
            this.draw();
            return;
        }
        this.bitmap = this.toCanvas(items);
        this.draw();
    }

    toCanvas(items) {
        let rows, cols, planes;
        const first = items[0];
        if (items.length === 3) {
            [rows, cols] = first.shape.length >= 2 ? first.shape.slice(-2) : [1, first.shape[0] || 1];
            planes = items.map((i) => i.data);
        } else if (first.shape.length === 3 && first.shape[0] === 3) {
            [, rows, cols] = first.shape;
            const n = rows * cols;
            planes = [0, 1, 2].map((k) => first.data.subarray(k * n, (k + 1) * n));
        } else {
            [rows, cols] = first.shape.length >= 2 ? first.shape.slice(-2) : [1, first.shape[0] || 1];
            planes = [first.data];
        }
        const c = this.off || (this.off = document.createElement("canvas"));
        c.width = cols; c.height = rows;
        const g = c.getContext("2d");
        const img = g.createImageData(cols, rows);
        const px = img.data;
        const clamp = (v) => (v > 1 ? 255 : v < 0 || !(v === v) ? 0 : Math.round(v * 255));
        if (planes.length === 3) {
            for (let i = 0; i < rows * cols; i++) {
                px[4 * i] = clamp(planes[0][i]); px[4 * i + 1] = clamp(planes[1][i]); px[4 * i + 2] = clamp(planes[2][i]); px[4 * i + 3] = 255;
            }
        } else {
            const table = colorTable(this.format === "rgb" ? "gray" : this.format);
            for (let i = 0; i < rows * cols; i++) {
                const t = table[clamp(planes[0][i])];
                px[4 * i] = t[0]; px[4 * i + 1] = t[1]; px[4 * i + 2] = t[2]; px[4 * i + 3] = 255;
            }
        }
        g.putImageData(img, 0, 0);
        return c;
    }

    draw() {
        if (!this.bitmap || !this.fit()) return;
        const g = this.g, w = this.width, h = this.height;
        const iw = this.bitmap.width || this.bitmap.naturalWidth, ih = this.bitmap.height || this.bitmap.naturalHeight;
        const scale = this.str(["scale"], "both");
        let dw = w, dh = h;
        if (scale === "none") { dw = iw; dh = ih; }
        else if (scale === "width") { dw = w; dh = ih * (w / iw); }
        else if (scale === "height") { dh = h; dw = iw * (h / ih); }
        g.imageSmoothingEnabled = iw >= w / 2;
        const fx = this.bool(["flipXCanvas", "flip_x_canvas"]), fy = this.bool(["flipYCanvas", "flip_y_canvas"]);
        g.save();
        g.translate(fx ? dw : 0, fy ? dh : 0);
        g.scale(fx ? -1 : 1, fy ? -1 : 1);
        g.drawImage(this.bitmap, 0, 0, dw, dh);
        g.restore();
    }

    click(e) {
        const command = this.commandTarget("command");
        if (!command) return;
        const r = this.canvas.getBoundingClientRect();
        this.sendCommand(command, (e.clientX - r.left) / r.width, (e.clientY - r.top) / r.height, 1);
    }
}
