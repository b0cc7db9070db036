// Axes for the canvas widgets that are not time plots (bar graph, scatter, histogram,
// boxplot, event raster): round tick values, the plotting box inside the labels, and the drawing.

/** About n round values covering lo..hi (1, 2 or 5 times a power of ten apart). */
export function niceTicks(lo, hi, n = 5) {
    if (!Number.isFinite(lo) || !Number.isFinite(hi)) return [];
    if (hi <= lo) hi = lo + 1;
    const raw = (hi - lo) / Math.max(1, n);
    const p = 10 ** Math.floor(Math.log10(raw));
    const step = [1, 2, 5, 10].map((m) => m * p).find((s) => s >= raw) || 10 * p;
    const out = [];
    for (let v = Math.ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) out.push(Math.abs(v) < step * 1e-9 ? 0 : v);
    return out;
}

/** A data range with a margin; a flat one gets a unit width; [lo, hi] fixed when given. */
export function dataRange(values, fixedLo, fixedHi, includeZero = false) {
    let lo = Infinity, hi = -Infinity;
    for (const v of values) if (Number.isFinite(v)) { if (v < lo) lo = v; if (v > hi) hi = v; }
    if (!Number.isFinite(lo)) { lo = 0; hi = 1; }
    if (includeZero) { lo = Math.min(lo, 0); hi = Math.max(hi, 0); }
    if (hi - lo < 1e-12) { lo -= 0.5; hi += 0.5; } else { const m = (hi - lo) * 0.05; lo -= m; hi += m; }
    return [fixedLo ?? lo, fixedHi ?? hi];
}

function label(v) {
    const a = Math.abs(v);
    if (a !== 0 && (a >= 1e5 || a < 1e-3)) return v.toExponential(1);
    return String(Math.round(v * 1e6) / 1e6);
}

/** The mapping of data ranges xr, yr onto a plotting box {left, top, right, bottom}
 *  (y upwards): {x(v), y(v), box}. */
export function mapping(box, xr, yr) {
    const { left, top, right, bottom } = box;
    return {
        x: (v) => left + ((v - xr[0]) / (xr[1] - xr[0] || 1)) * (right - left),
        y: (v) => bottom - ((v - yr[0]) / (yr[1] - yr[0] || 1)) * (bottom - top),
        box,
    };
}

/**
 * Draw axes with tick labels around a plotting box in a w x h canvas. xr and yr are
 * [lo, hi]; xTicks and yTicks, lists of [value, text], replace the round values of an axis
 * (categories; [] for none). Returns the mapping {x(v), y(v), box: {left, top, right, bottom}}.
 */
export function drawAxes(g, w, h, xr, yr, { color = "#333", grid = "#ddd", xLabel = "", yLabel = "", xTicks = null, yTicks = null } = {}) {
    const left = 44, bottom = h - (xLabel ? 28 : 18), top = 6, right = w - 8;
    const { x, y, box } = mapping({ left, top, right, bottom }, xr, yr);
    g.save();
    g.font = "10px sans-serif";
    g.lineWidth = 0.5;
    g.strokeStyle = grid;
    g.fillStyle = color;
    g.textAlign = "right";
    g.textBaseline = "middle";
    const ys = yTicks || niceTicks(yr[0], yr[1], Math.max(2, Math.floor((bottom - top) / 30))).map((v) => [v, label(v)]);
    for (const [v, text] of ys) {
        g.beginPath(); g.moveTo(left, y(v)); g.lineTo(right, y(v)); g.stroke();
        g.fillText(text, left - 4, y(v));
    }
    g.textAlign = "center";
    g.textBaseline = "top";
    const xs = xTicks || niceTicks(xr[0], xr[1], Math.max(2, Math.floor((right - left) / 60))).map((v) => [v, label(v)]);
    for (const [v, text] of xs) {
        g.beginPath(); g.moveTo(x(v), top); g.lineTo(x(v), bottom); g.stroke();
        g.fillText(text, x(v), bottom + 3);
    }
    g.strokeStyle = color;
    g.beginPath(); g.moveTo(left, top); g.lineTo(left, bottom); g.lineTo(right, bottom); g.stroke();
    if (xLabel) g.fillText(xLabel, (left + right) / 2, bottom + 15);
    if (yLabel) {
        g.translate(9, (top + bottom) / 2); g.rotate(-Math.PI / 2);
        g.textBaseline = "middle"; g.fillText(yLabel, 0, 0);
    }
    g.restore();
    return { x, y, box };
}
