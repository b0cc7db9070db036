// heat-map: a grid with the fire colour map by default (Ikaros 3).
import Grid from "./grid.js";

export default class HeatMap extends Grid {
    static defaultTitle = "Heat Map";
}
