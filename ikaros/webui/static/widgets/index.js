// The widget table: class name (as in the model file, kebab-case) -> the module that
// implements it. A new widget type is one new file plus one line here.
export const WIDGETS = {
    "bar-graph": () => import("./bar-graph.js"),
    "plot": () => import("./plot.js"),
    "table": () => import("./table.js"),
    "grid": () => import("./grid.js"),
    "heat-map": () => import("./heat-map.js"),
    "image": () => import("./image.js"),
    "marker": () => import("./marker.js"),
    "path": () => import("./path.js"),
    "text": () => import("./text.js"),
    "rectangle": () => import("./rectangle.js"),
    "button": () => import("./button.js"),
    "switch": () => import("./switch.js"),
    "drop-down-menu": () => import("./drop-down-menu.js"),
    "slider-horizontal": () => import("./slider-horizontal.js"),
    "slider-vertical": () => import("./slider-vertical.js"),
    "canvas3d": () => import("./canvas3d.js"),
    "grid-world": () => import("./grid-world.js"),
    "planar-arm": () => import("./planar-arm.js"),
    "world-2d": () => import("./world-2d.js"),
    "event-raster": () => import("./event-raster.js"),
    "scatter-plot": () => import("./scatter-plot.js"),
    "histogram": () => import("./histogram.js"),
    "boxplot": () => import("./boxplot.js"),
    "polar-plot": () => import("./polar-plot.js"),
    "vector-field": () => import("./vector-field.js"),
    "joystick": () => import("./joystick.js"),
    "color-picker": () => import("./color-picker.js"),
    "epi-head": () => import("./epi-head.js"),
    "trace": () => import("./trace.js"),
    "navigation-hud": () => import("./navigation-hud.js"),
    "pan-tilt-hud": () => import("./pan-tilt-hud.js"),
    "surface-plot": () => import("./surface-plot.js"),
    "target-boxes": () => import("./target-boxes.js"),
};

// Other spellings met in model files.
export const ALIASES = {
    "slider": "slider-horizontal",
    "check-box": "switch",
    "checkbox": "switch",
    "drop-down": "drop-down-menu",
    "canvas-3d": "canvas3d",
    "canvas3-d": "canvas3d",
    "three-d": "canvas3d",
    "label": "text",
    "world2-d": "world-2d", "world2d": "world-2d",
    "scatter": "scatter-plot", "polar": "polar-plot", "raster": "event-raster",
    "box-plot": "boxplot", "colour-picker": "color-picker", "epihead": "epi-head",
};

/** The widget class for a class name, or null. */
export async function widgetClass(name) {
    let key = String(name || "").trim();
    if (!WIDGETS[key]) key = key.replace(/([a-z0-9])([A-Z])/g, "$1-$2").replace(/_/g, "-").toLowerCase();
    key = ALIASES[key] || key;
    const load = WIDGETS[key];
    if (!load) return null;
    return (await load()).default;
}
