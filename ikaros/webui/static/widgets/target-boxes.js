// target-boxes: rectangles from the rows of a matrix, drawn over what lies under the widget
// (an image, typically): the targets of a detector or a tracker.
// Every row is one box, from column select|select_x on, in the form box_format gives:
//   xywh    x, y of the top-left corner, width, height (the default)
//   center  x, y of the centre, width, height
//   xyxy    two opposite corners x0, y0, x1, y1
//   corners four corners (x, y), e.g. FACE_BOUNDS or TRACKER_BOUNDS: their bounding box.
// A buffer whose rows are shorter than one box (DepthContourTrace's BOX, 4 x 2) is read as
// one list, a box per 4 values (8 for corners). A box without width or height is an unused
// row (detectors fill the rows past the last target with 0) and is not drawn. The value
// after a row's box is its score.
// Attributes: source, box_format, select|select_x, count|box_count (0: all),
// box_color|color|stroke_color (comma list, cycles per box), fill_color|fill (none; a comma
// list cycles, "none" for a box without), fill_opacity (0.2), line_width (2), labels (comma
// list, one per row), show_score (no), score_decimals (2), min_score (boxes with a lower
// score are not drawn), label_color (white, on the box's colour), font; coordinates
// x_min|min_x .. y_max|max_y (0..1), flips.
import { CanvasWidget, asRows, formatNumber } from "./widget.js";

export const BOX_FORMATS = { xywh: 4, center: 4, xyxy: 4, corners: 8 };

/** [left, top, right, bottom] of a box's values in a format (data coordinates). */
export function boxEdges(v, format) {
    if (format === "center") return [v[0] - v[2] / 2, v[1] - v[3] / 2, v[0] + v[2] / 2, v[1] + v[3] / 2];
    if (format === "xyxy") return [Math.min(v[0], v[2]), Math.min(v[1], v[3]), Math.max(v[0], v[2]), Math.max(v[1], v[3])];
    if (format === "corners") {
        const xs = [v[0], v[2], v[4], v[6]], ys = [v[1], v[3], v[5], v[7]];
        return [Math.min(...xs), Math.min(...ys), Math.max(...xs), Math.max(...ys)];
    }
    return [v[0], v[1], v[0] + v[2], v[1] + v[3]];
}

/** The boxes of a buffer: [{edges, score (or null), index}]. */
export function boxesFrom(widget, item) {
    let format = widget.str(["box_format"], "xywh");
    if (!BOX_FORMATS[format]) format = "xywh";
    const size = BOX_FORMATS[format];
    const first = widget.int(["select", "select_x"], 0);
    let rows = asRows(item).map((r) => Array.from(r).slice(first));
    if (rows.length && rows[0].length < size) {
        const flat = rows.flat();
        rows = [];
        for (let i = 0; i + size <= flat.length; i += size) rows.push(flat.slice(i, i + size));
    }
    const count = widget.int(["count", "box_count"], 0);
    const boxes = [];
    rows.forEach((row, index) => {
        if (row.length < size || (count && boxes.length >= count)) return;
        const edges = boxEdges(row, format);
        if (!(edges[2] > edges[0] && edges[3] > edges[1])) return;
        boxes.push({ edges, score: row.length > size ? row[size] : null, index });
    });
    return boxes;
}

export default class TargetBoxes extends CanvasWidget {
    subscriptions() { const p = this.path("source"); return p ? [{ path: p, format: "raw" }] : []; }

    update(frame) {
        const item = frame.get(this.path("source"));
        if (!item) return;
        this.boxes = boxesFrom(this, item);
        this.draw();
    }

    draw() {
        if (!this.boxes || !this.fit()) return;
        const g = this.g, map = this.coordinates();
        const colors = this.list(["box_color", "color", "stroke_color"], ["#ff3030"]);
        const fills = this.list(["fill_color", "fill"], []);
        const opacity = this.num(["fill_opacity"], 0.2);
        const labels = this.list(["labels"], []);
        const showScore = this.bool(["show_score"], false);
        const decimals = this.int(["score_decimals"], 2);
        const minScore = this.num(["min_score"], -Infinity);
        g.lineWidth = this.num(["line_width", "lineWidth"], 2);
        g.font = this.str(["font"], "11px sans-serif");
        g.textBaseline = "bottom";
        this.drawn = [];
        this.boxes.forEach((b) => {
            if (b.score !== null && b.score < minScore) return;
            const k = this.drawn.length;
            const [x0, x1] = [map.x(b.edges[0]), map.x(b.edges[2])].sort((p, q) => p - q);
            const [y0, y1] = [map.y(b.edges[1]), map.y(b.edges[3])].sort((p, q) => p - q);
            const color = colors[k % colors.length];
            const fill = fills.length ? fills[k % fills.length] : "none";
            if (fill && fill !== "none") {
                g.globalAlpha = opacity;
                g.fillStyle = fill;
                g.fillRect(x0, y0, x1 - x0, y1 - y0);
                g.globalAlpha = 1;
            }
            g.strokeStyle = color;
            g.strokeRect(x0, y0, x1 - x0, y1 - y0);
            const text = [labels[b.index] ?? "", showScore && b.score !== null ? formatNumber(b.score, decimals) : ""].filter(Boolean).join(" ");
            this.drawn.push({ box: [x0, y0, x1, y1], text });
            if (!text) return;
            // the label on the box's colour, above its top-left corner (inside at the top)
            const tw = g.measureText(text).width + 6, th = 14;
            const ly = y0 - th >= 0 ? y0 - th : y0;
            g.fillStyle = color;
            g.fillRect(x0 - g.lineWidth / 2, ly, tw, th);
            g.fillStyle = this.str(["label_color"], "#fff");
            g.fillText(text, x0 - g.lineWidth / 2 + 3, ly + th - 2);
        });
    }
}
