// marker: points or labels at coordinates (scatter plots, overlays).
// Attributes: source (rows of x,y pairs); order (col: every pair is a point with its own
// colour; row: the pairs of a row are one series with one colour); select|select_x (first column),
// selectValue|select_value_column (the column labelled by label_type "value"),
// count|point_count (0: all), markerType|marker_type (none/circle/cross/square), size
// (fraction of the widget size), color|stroke_color, fill|fill_color (cycle per point, or per
// series with order=row), lineWidth|line_width, labelType|label_type (none/labels/
// alphabetical/numbered/x_value/y_value/z_value/xy_value/value), labels, labelFont|
// label_font, labelDecimals|label_decimals, labelPrefix|label_prefix, labelPostfix|
// label_suffix, labelAlign|label_align, labelBaseline|label_baseline, labelOffsetX/Y|
// label_offset_x/y; coordinates: min_x|x_min, max_x|x_max, min_y|y_min, max_y|y_max, flips.
import { CanvasWidget, asRows, formatNumber } from "./widget.js";

/**
 * Points from coordinate rows. Every row holds x,y pairs from column select|select_x on.
 * With order "col" every pair is its own point (series = point); with order "row" the
 * pairs of a row form one series (series = row). Returns [{x, y, z, value, series, row}].
 */
export function pointsFrom(widget, item) {
    const rows = asRows(item);
    const byRow = widget.str(["order"], "col") === "row";
    const sel = widget.int(["select", "select_x"], 0);
    const selValue = widget.int(["selectValue", "select_value_column"], -1);
    const count = widget.int(["count", "point_count"], 0);
    const pts = [];
    rows.forEach((row, r) => {
        for (let i = sel; i + 1 < row.length; i += 2) {
            if (count && pts.length >= count) return;
            pts.push({ x: row[i], y: row[i + 1], z: row[i + 2] ?? 0,
                value: selValue >= 0 ? row[selValue] : row[i], series: byRow ? r : pts.length, row: r });
        }
    });
    return pts;
}

export default class Marker extends CanvasWidget {
    subscriptions() { const p = this.path("source"); return p ? [{ path: p, format: "raw" }] : []; }

    update(frame) {
        const item = frame.get(this.path("source"));
        if (!item) return;
        this.points = pointsFrom(this, item);
        this.draw();
    }

    label(p, i) {
        const type = this.str(["labelType", "label_type"], "none");
        const d = this.int(["labelDecimals", "label_decimals"], 2);
        const labels = this.list(["labels"], []);
        switch (type) {
            case "labels": return labels.length ? labels[i % labels.length] : "";
            case "alphabetical": return String.fromCharCode(65 + (i % 26));
            case "numbered": return String(i + 1);
            case "x_value": return formatNumber(p.x, d);
            case "y_value": return formatNumber(p.y, d);
            case "z_value": return formatNumber(p.z, d);
            case "xy_value": return formatNumber(p.x, d) + ", " + formatNumber(p.y, d);
            case "value": return formatNumber(p.value, d);
            default: return null;
        }
    }

    draw() {
        if (!this.points || !this.fit()) return;
        const g = this.g, map = this.coordinates();
        const type = this.str(["markerType", "marker_type"], "circle");
        const size = this.num(["size"], 0.02) * Math.min(this.width, this.height);
        const strokes = this.colors(["color", "stroke_color"]);
        const fills = this.list(["fill", "fill_color"], strokes);
                const prefix = this.str(["labelPrefix", "label_prefix"]), postfix = this.str(["labelPostfix", "label_suffix", "label_postfix"]);
        g.font = this.str(["labelFont", "label_font"], "12px sans-serif");
        g.textAlign = this.str(["labelAlign", "label_align"], "center");
        g.textBaseline = this.str(["labelBaseline", "label_baseline"], "middle");
        const ox = this.num(["labelOffsetX", "label_offset_x"], 0), oy = this.num(["labelOffsetY", "label_offset_y"], -(size + 8));
        this.lineStyle(g);
        this.points.forEach((p, i) => {
            const k = p.series;
            const x = map.x(p.x), y = map.y(p.y);
            g.strokeStyle = strokes[k % strokes.length];
            g.fillStyle = fills[k % fills.length];
            if (type === "circle") {
                g.beginPath(); g.arc(x, y, Math.max(size, 1), 0, 2 * Math.PI); g.fill(); g.stroke();
            } else if (type === "cross") {
                g.beginPath(); g.moveTo(x - size, y - size); g.lineTo(x + size, y + size);
                g.moveTo(x + size, y - size); g.lineTo(x - size, y + size); g.stroke();
            } else if (type === "square") {
                g.fillRect(x - size, y - size, 2 * size, 2 * size); g.strokeRect(x - size, y - size, 2 * size, 2 * size);
            }
            const text = this.label(p, i);
            if (text !== null && text !== "") {
                g.fillStyle = this.cssVar("--text-color", "#333");
                g.fillText(prefix + text + postfix, x + ox, y + oy);
            }
        });
    }
}
