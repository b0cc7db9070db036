// pan-tilt-hud: see hud.js.
export { PanTiltHud as default } from "./hud.js";
