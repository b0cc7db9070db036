// navigation-hud: see hud.js.
export { NavigationHud as default } from "./hud.js";
