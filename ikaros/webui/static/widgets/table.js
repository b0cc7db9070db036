// table: the values of a buffer as an HTML table.
// Attributes: source, label_x, label_y (comma lists), direction="flip x/y" | transpose,
// decimals (4), colorize (positive/negative values coloured), scrollable.
import { Widget, asRows, formatNumber } from "./widget.js";

export default class Table extends Widget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        this.table = document.createElement("table");
        this.table.className = "data-table";
        this.body.appendChild(this.table);
        this.body.style.overflow = this.bool(["scrollable"], false) ? "auto" : "hidden";
        this.shapeKey = "";
    }

    subscriptions() { const p = this.path("source"); return p ? [{ path: p, format: "raw" }] : []; }

    update(frame) {
        const item = frame.get(this.path("source"));
        if (!item) return;
        let rows = asRows(item).map((r) => Array.from(r));
        const flip = this.bool(["transpose"], false) || /flip/.test(this.str(["direction"], ""));
        if (flip && rows.length) rows = rows[0].map((_, c) => rows.map((r) => r[c]));
        const labelsX = this.list(["label_x"], []), labelsY = this.list(["label_y"], []);
        const key = rows.length + "x" + (rows[0] || []).length;
        if (key !== this.shapeKey) {
            this.shapeKey = key;
            this.table.textContent = "";
            if (labelsX.length) {
                const tr = this.table.insertRow();
                if (labelsY.length) tr.appendChild(document.createElement("th"));
                (rows[0] || []).forEach((_, c) => { const th = document.createElement("th"); th.textContent = labelsX[c] ?? ""; tr.appendChild(th); });
            }
            rows.forEach((row, r) => {
                const tr = this.table.insertRow();
                if (labelsY.length) { const th = document.createElement("th"); th.textContent = labelsY[r] ?? ""; tr.appendChild(th); }
                row.forEach(() => tr.insertCell());
            });
        }
        const decimals = this.int(["decimals"], 4);
        const colorize = this.bool(["colorize"], true);
        const offset = labelsX.length ? 1 : 0;
        rows.forEach((row, r) => {
            const tr = this.table.rows[r + offset];
            const first = labelsY.length ? 1 : 0;
            row.forEach((v, c) => {
                const td = tr.cells[c + first];
                td.textContent = formatNumber(v, decimals);
                td.className = colorize ? (v > 0 ? "positive" : v < 0 ? "negative" : "zero") : "";
            });
        });
    }
}
