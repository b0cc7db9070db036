// What of a time plot's axes fits its size. The plotting area keeps at least MIN_WIDTH x
// MIN_HEIGHT pixels, and the axes are drawn beside it, never over it. A smaller plot shows
// fewer tick values first (the axes' spacing), then drops the axis titles, then the x axis's
// tick values, then the y axis's; the top keeps room for the highest y value's text, the
// right for half of the last x value's.

export const MIN_WIDTH = 40, MIN_HEIGHT = 20;
const X_VALUES = 18;        // tick mark 3, gap 5, 10 px text
const TITLE = 13;           // an axis title: 10 px text and a gap
const TOP = 6;              // half the text of the highest y value
const RIGHT = 18;           // half the text of the last x value
const BOTTOM = 6;           // half the text of the lowest y value, when no x values are below
const EDGE = 2;

/** The width of the y axis's values: the longest text of them, its tick and gap. */
export function yValuesWidth(texts, font = "10px sans-serif") {
    const g = document.createElement("canvas").getContext("2d");
    g.font = font;
    const widest = Math.max(0, ...texts.map((t) => g.measureText(String(t)).width));
    return Math.ceil(widest) + 12;
}

/**
 * The parts of the axes that fit in w x h: {xValues, xTitle, yValues, yTitle} (booleans) and
 * the padding [top, right, bottom, left]. ``want`` says which parts the plot asks for
 * ({xAxis, yAxis, xTitle, yTitle}); ``yWidth`` is the width its y values take.
 */
export function axesLayout(w, h, want, yWidth = 38) {
    const parts = {
        xValues: want.xAxis, xTitle: want.xAxis && want.xTitle,
        yValues: want.yAxis, yTitle: want.yAxis && want.yTitle,
    };
    const below = () => (parts.xValues ? X_VALUES : parts.yValues ? BOTTOM : EDGE);
    const height = () => TOP + below() + (parts.xTitle ? TITLE : 0);
    const width = () => (parts.yValues ? yWidth : EDGE) + (parts.yTitle ? TITLE : 0)
        + (parts.xValues ? RIGHT : EDGE);
    for (const drop of ["xTitle", "yTitle", "xValues", "yValues"]) {
        if (h - height() >= MIN_HEIGHT && w - width() >= MIN_WIDTH) break;
        parts[drop] = false;
    }
    const padding = [TOP, parts.xValues ? RIGHT : EDGE, parts.xValues ? 0 : below(),
        parts.yValues || parts.yTitle ? 0 : EDGE];
    return { ...parts, padding, xSize: X_VALUES, titleSize: TITLE };
}
