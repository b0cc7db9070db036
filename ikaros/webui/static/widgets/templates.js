// What each widget class reads, for the editor's widget inspector: every attribute with
// its type, so each gets the control its type needs. A type is "number", "int", "bool",
// "color" (a colour or a comma list of colours), "source" (an output), "parameter", "text",
// or a list of choices. The geometry and the attributes every widget reads (title, frame,
// style) are shown by the inspector itself.

const RANGE = { min: "number", max: "number", auto_range: "bool", include_zero: "bool" };
const LINES = { stroke_color: "color", line_width: "number", line_cap: ["butt", "round", "square"], line_join: ["miter", "round", "bevel"] };
const COORDS = { x_min: "number", x_max: "number", y_min: "number", y_max: "number", flip_x_canvas: "bool", flip_y_canvas: "bool" };
const COLOR_MAPS = ["gray", "fire", "spectrum", "red", "green", "blue", "custom", "rgb"];
const CAMERA = { camera_pos: "text", camera_target: "text", camera_distance: "number", show_axis: "bool", show_ground_grid: "bool", scene_background: "color" };

export const TEMPLATES = {
    "bar-graph": { source: "source", direction: ["vertical", "horizontal"], transpose: "bool", labels: "text", fill_color: "color", ...LINES, ...RANGE, unit: "text", show_axis: "bool", show_values: "bool", decimals: "int" },
    "plot": { source: "source", select: "text", buffer_size: "int", ...RANGE, unit: "text", x_label: "text", show_x_axis: "bool", show_y_axis: "bool", stroke_color: "color", line_width: "number", decimals: "int" },
    "table": { source: "source", label_x: "text", label_y: "text", transpose: "bool", decimals: "int", colorize: "bool", scrollable: "bool" },
    "grid": { source: "source", color_map: COLOR_MAPS, color_map_colors: "text", min: "number", max: "number", labels: "text", label_width: "int", shape: ["rectangle", "square", "circle"], size: "number", command: "text", parameter: "parameter", on_value: "number", off_value: "number", flip_x_canvas: "bool", flip_y_canvas: "bool" },
    "image": { source: "source", format: ["gray", "fire", "spectrum", "red", "green", "blue", "rgb"], file: "text", index_source: "source", scale: ["both", "none", "width", "height"], opacity: "number", command: "text", ...COORDS },
    "marker": { source: "source", order: ["col", "row"], select_x: "int", point_count: "int", marker_type: ["circle", "cross", "square", "none"], size: "number", fill_color: "color", ...LINES, label_type: ["none", "labels", "alphabetical", "numbered", "x_value", "y_value", "z_value", "xy_value", "value"], labels: "text", label_decimals: "int", ...COORDS },
    "path": { source: "source", order: ["col", "row"], select_x: "int", point_count: "int", fill_color: "color", ...LINES, close: "bool", arrow: "bool", ...COORDS },
    "text": { text: "text", parameter: "parameter", select_source: "source", strings: "text", prefix: "text", postfix: "text", separator: "text", decimals: "int", text_color: "color", font: "text", text_align: ["left", "center", "right"], padding: "number", placeholder: "text" },
    "rectangle": { label: "text", fill_color: "color", stroke_color: "color", text_color: "color", font: "text", text_align: ["left", "center", "right"], vertical_align: ["top", "middle", "bottom"], padding: "number" },
    "button": { label: "text", type: ["push", "toggle", "radio", "multi"], command: "text", release_command: "text", parameter: "parameter", value: "number", release_value: "number", values: "text", labels: "text", select_x: "int", select_y: "int", enabled_source: "source", text_color: "color", background_color: "color", tooltip: "text" },
    "switch": { parameter: "parameter", labels: "text", value: "number", select_x: "int", select_y: "int", control_count: "int", enabled_source: "source" },
    "drop-down-menu": { parameter: "parameter", options: "text", value_type: ["number", "string"], select_x: "int", label: "text", label_width: "int", enabled_source: "source" },
    "slider-horizontal": { parameter: "parameter", command: "text", select_x: "int", select_y: "int", control_count: "int", labels: "text", min: "number", max: "number", step: "number", show_values: "bool", enabled_source: "source" },
    "canvas3d": { source: "source", show_points: "bool", point_color: "color", point_size: "number", show_lines: "bool", line: "text", line_color: "color", show_models: "bool", models: "text", model_color: "color", ...CAMERA },
    "surface-plot": { source: "source", display_mode: ["surface", "wireframe", "surface-wireframe", "points"], color_map: COLOR_MAPS, height_scale: "number", value_min: "number", value_max: "number", ...CAMERA },
    "event-raster": { source: "source", history: "int", labels: "text", stroke_color: "color" },
    "trace": { source: "source", x_source: "source", y_source: "source", select_x: "int", select_y: "int", history_length: "int", stroke_color: "color", line_width: "number", ...COORDS },
    "scatter-plot": { x_source: "source", y_source: "source", source: "source", x_min: "number", x_max: "number", y_min: "number", y_max: "number", x_label: "text", y_label: "text", stroke_color: "color", size: "number" },
    "histogram": { source: "source", bins: "int", histogram_min: "number", histogram_max: "number", fill_color: "color", x_label: "text" },
    "boxplot": { source: "source", labels: "text", fill_color: "color", y_min: "number", y_max: "number" },
    "polar-plot": { source: "source", max: "number", labels: "text", stroke_color: "color", fill: "bool" },
    "vector-field": { source: "source", x_source: "source", y_source: "source", vector_scale: "number", stride: "int", stroke_color: "color" },
    "joystick": { x_parameter: "parameter", y_parameter: "parameter", select_x: "int", select_y: "int", range: ["bipolar", "unipolar"], return_to_center: "bool" },
    "color-picker": { parameter: "parameter", select_y: "int", show_values: "bool" },
    "epi-head": { eye_direction_source: "source", pupil_size_source: "source", gaze_in_degrees: "bool", eye_color: "color", mouth_color: "color", head_color: "color", vergence: "number" },
    "navigation-hud": { heading_source: "source", target_source: "source", unit: ["degrees", "radians"], stroke_color: "color" },
    "pan-tilt-hud": { source: "source", target_source: "source", unit: ["degrees", "radians"], pan_range: "text", tilt_range: "text", stroke_color: "color" },
    "target-boxes": { source: "source", box_format: ["xywh", "center", "xyxy", "corners"], select_x: "int", box_count: "int", box_color: "color", fill_color: "color", fill_opacity: "number", line_width: "number", labels: "text", show_score: "bool", score_decimals: "int", min_score: "number", label_color: "color", font: "text", ...COORDS },
    "grid-world": { module: "text" },
    "planar-arm": { module: "text", trail: "int", ...COORDS },
    "world-2d": { module: "text", show_rays: "bool", ...COORDS },
};
TEMPLATES["heat-map"] = TEMPLATES.grid;
TEMPLATES["slider-vertical"] = TEMPLATES["slider-horizontal"];

// Older spellings of the same attributes: a file's own spelling is the one edited.
export const SPELLINGS = {
    stroke_color: ["color"], fill_color: ["fill"], line_width: ["lineWidth"], line_cap: ["lineCap"], line_join: ["lineJoin"],
    min: ["y_min", "value_min"], max: ["y_max", "value_max"], auto_range: ["auto"], select_x: ["select", "xindex"], select_y: ["yindex"],
    point_count: ["count"], marker_type: ["markerType"], label_type: ["labelType"], label_decimals: ["labelDecimals"],
    release_command: ["commandUp"], release_value: ["valueUp"], enabled_source: ["enableSource"], control_count: ["count"], box_count: ["count"], box_color: ["color", "stroke_color"],
    x_min: ["min_x"], x_max: ["max_x"], flip_x_canvas: ["flipXCanvas"], flip_y_canvas: ["flipYCanvas"], color_map: ["fill"],
    color_map_colors: ["colorTable"], direction: ["orientation"], options: ["list"], eye_direction_source: ["gazeSource"],
};

/** The attributes of a widget class: [[name, type], ...] (empty for an unknown class). */
export function templateOf(cls) {
    return Object.entries(TEMPLATES[cls] || {});
}
