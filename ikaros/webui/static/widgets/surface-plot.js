// surface-plot: a matrix as a 3-D surface (height = value), coloured by value, in the
// canvas3d scene (drag to orbit, wheel to zoom). The surface spans -1..1 in x and y; heights
// are scaled to -height_scale..height_scale over the value range (auto unless value_min and
// value_max are given).
// Attributes: source, display_mode (surface, wireframe, surface-wireframe, points),
// color_map (fire, spectrum, gray, ...), height_scale (0.5), value_min, value_max, and the
// camera and scene attributes of canvas3d.
import * as THREE from "three";
import Canvas3D from "./canvas3d.js";
import { colorTable } from "./widget.js";

export default class SurfacePlot extends Canvas3D {
    subscriptions() { const p = this.path("source"); return p ? [{ path: p, format: "raw" }] : []; }

    update(frame) {
        const item = frame.get(this.path("source"));
        if (!item) return;
        const shape = item.shape.length >= 2 ? item.shape.slice(-2) : [1, item.data.length];
        this.build(shape[0], shape[1], item.data);
        this.render();
    }

    build(rows, cols, data) {
        let lo = Infinity, hi = -Infinity;
        for (const v of data) if (Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
        if (this.raw(["value_min"]) !== undefined) lo = this.num(["value_min"]);
        if (this.raw(["value_max"]) !== undefined) hi = this.num(["value_max"]);
        if (!(hi > lo)) { hi = lo + 1; }
        this.range = [lo, hi];
        const key = `${rows}x${cols}`;
        if (this.key !== key) {
            this.key = key;
            if (this.surface) this.items.remove(this.surface);
            const geometry = new THREE.PlaneGeometry(2, 2, Math.max(1, cols - 1), Math.max(1, rows - 1));
            geometry.setAttribute("color", new THREE.BufferAttribute(new Float32Array(geometry.attributes.position.count * 3), 3));
            const mode = this.str(["display_mode"], "surface");
            this.surface = new THREE.Group();
            if (mode === "points") {
                this.surface.add(new THREE.Points(geometry, new THREE.PointsMaterial({ size: 0.04, vertexColors: true })));
            } else {
                if (mode !== "wireframe") this.surface.add(new THREE.Mesh(geometry, new THREE.MeshLambertMaterial({ vertexColors: true, side: THREE.DoubleSide })));
                if (mode.includes("wireframe")) this.surface.add(new THREE.Mesh(geometry, new THREE.MeshBasicMaterial({ color: 0x333333, wireframe: true })));
            }
            this.geometry = geometry;
            this.items.add(this.surface);
        }
        const table = colorTable(this.str(["color_map"], "fire"), this.str(["color_map_colors"]));
        const pos = this.geometry.attributes.position, col = this.geometry.attributes.color;
        const scale = this.num(["height_scale"], 0.5);
        // PlaneGeometry's vertices run row by row from the top left, as the matrix does
        for (let i = 0; i < pos.count; i++) {
            const r = Math.floor(i / cols), c = i % cols;
            const v = data[(rows === 1 ? 0 : r) * cols + c] ?? 0;
            const f = Math.max(0, Math.min(1, (v - lo) / (hi - lo)));
            pos.setZ(i, (f * 2 - 1) * scale);
            const [R, G, B] = table[Math.round(f * 255)];
            col.setXYZ(i, R / 255, G / 255, B / 255);
        }
        pos.needsUpdate = true;
        col.needsUpdate = true;
        this.geometry.computeVertexNormals();
    }
}
