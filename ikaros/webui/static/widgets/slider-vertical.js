// slider-vertical: vertical sliders; the same attributes as slider-horizontal.
import SliderHorizontal from "./slider-horizontal.js";

export default class SliderVertical extends SliderHorizontal {
    static vertical = true;
}
