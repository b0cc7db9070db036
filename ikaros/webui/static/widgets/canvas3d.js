// canvas3d: a three.js 3D view of rows of 4x4 transforms (row-major, 16 numbers a row), in
// Ikaros axes (x forward, y left, z up), drawn as points, lines and models.
// Attributes: source|matrix, show_points (yes), point_color, point_size, show_lines,
// line_color, line_width, line ("0-1,1-2": the segments between rows; default: row to row),
// show_models, models|model (a comma list, one per row: box, sphere, cylinder, cone, axes,
// or a .glb/.gltf file beside the model), model_color, show_axis, show_ground_grid,
// camera_pos|camera ("x,y,z"), camera_target|look_at ("x,y,z") or look_at_x/y/z,
// camera_distance, offset_x/y/z, scene_background. Drag to orbit, wheel to zoom.
import * as THREE from "three";
import { fileURL } from "../api.js";
import { Widget, asRows } from "./widget.js";

function triple(text, def) {
    if (!text) return def;
    const v = String(text).split(",").map(parseFloat);
    return v.length === 3 && v.every(Number.isFinite) ? v : def;
}

export default class Canvas3D extends Widget {
    constructor(attrs, ctx) {
        super(attrs, ctx);
        this.body.classList.add("canvas3d");
        this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
        this.renderer.setPixelRatio(window.devicePixelRatio || 1);
        this.canvas = this.renderer.domElement;
        this.body.appendChild(this.canvas);
        this.scene = new THREE.Scene();
        this.root = new THREE.Group();                  // Ikaros axes -> three.js axes
        this.root.rotation.x = -Math.PI / 2;
        this.root.position.set(this.num(["offset_x"], 0), this.num(["offset_z"], 0), -this.num(["offset_y"], 0));
        this.scene.add(this.root);
        this.scene.add(new THREE.AmbientLight(0xffffff, 1.2));
        const sun = new THREE.DirectionalLight(0xffffff, 1.5);
        sun.position.set(3, 5, 4);
        this.scene.add(sun);
        if (this.bool(["show_ground_grid", "show_grid"], true)) this.scene.add(new THREE.GridHelper(4, 8, 0x888888, 0x888888));
        if (this.bool(["show_axis", "show_axes"], true)) this.root.add(new THREE.AxesHelper(0.5));
        this.camera = new THREE.PerspectiveCamera(45, 1, 0.01, 1000);
        const target = this.attrs.look_at_x !== undefined
            ? [this.num(["look_at_x"], 0), this.num(["look_at_y"], 0), this.num(["look_at_z"], 0)]
            : triple(this.raw(["camera_target", "look_at"]), [0, 0, 0]);
        const pos = triple(this.raw(["camera_pos", "camera"]), null);
        this.target = new THREE.Vector3(target[0], target[2], -target[1]);
        const d = this.num(["camera_distance"], 3);
        if (pos) {
            const p = new THREE.Vector3(pos[0], pos[2], -pos[1]).sub(this.target);
            this.orbit = { r: p.length() || d, theta: Math.atan2(p.x, p.z), phi: Math.acos(Math.min(1, Math.max(-1, p.y / (p.length() || 1)))) };
        } else {
            this.orbit = { r: d, theta: Math.PI / 4, phi: Math.PI / 3 };
        }
        this.items = new THREE.Group();
        this.root.add(this.items);
        this.models = [];
        this.modelNames = this.list(["models", "model"], []);
        this.interact();
        this.transforms = [];
        this.placeCamera();
        requestAnimationFrame(() => this.render());
    }

    subscriptions() { const p = this.path("source", "matrix"); return p ? [{ path: p, format: "raw" }] : []; }

    interact() {
        let last = null;
        this.canvas.addEventListener("pointerdown", (e) => { last = [e.clientX, e.clientY]; this.canvas.setPointerCapture(e.pointerId); });
        this.canvas.addEventListener("pointermove", (e) => {
            if (!last) return;
            this.orbit.theta -= (e.clientX - last[0]) * 0.01;
            this.orbit.phi = Math.min(Math.PI - 0.05, Math.max(0.05, this.orbit.phi - (e.clientY - last[1]) * 0.01));
            last = [e.clientX, e.clientY];
            this.placeCamera(); this.render();
        });
        this.canvas.addEventListener("pointerup", () => { last = null; });
        this.canvas.addEventListener("wheel", (e) => {
            e.preventDefault();
            this.orbit.r *= Math.exp(e.deltaY * 0.001);
            this.placeCamera(); this.render();
        }, { passive: false });
    }

    placeCamera() {
        const { r, theta, phi } = this.orbit;
        this.camera.position.set(
            this.target.x + r * Math.sin(phi) * Math.sin(theta),
            this.target.y + r * Math.cos(phi),
            this.target.z + r * Math.sin(phi) * Math.cos(theta));
        this.camera.lookAt(this.target);
    }

    update(frame) {
        const item = frame.get(this.path("source", "matrix"));
        if (!item) return;
        this.transforms = asRows(item).filter((r) => r.length >= 16).map((r) => new THREE.Matrix4().set(...Array.from(r.subarray(0, 16))));
        this.rebuild();
        this.render();
    }

    model(i) {
        const name = this.modelNames.length ? this.modelNames[i % this.modelNames.length] : "box";
        const color = new THREE.Color(this.str(["model_color"], "#8899aa"));
        const mat = new THREE.MeshStandardMaterial({ color });
        const s = this.num(["model_size"], 0.1);
        const built = {
            box: () => new THREE.Mesh(new THREE.BoxGeometry(s, s, s), mat),
            sphere: () => new THREE.Mesh(new THREE.SphereGeometry(s / 2, 16, 12), mat),
            cylinder: () => new THREE.Mesh(new THREE.CylinderGeometry(s / 2, s / 2, s, 16).rotateX(Math.PI / 2), mat),
            cone: () => new THREE.Mesh(new THREE.ConeGeometry(s / 2, s, 16).rotateX(Math.PI / 2), mat),
            axes: () => new THREE.AxesHelper(s),
        }[name.toLowerCase()];
        const holder = new THREE.Group();
        holder.matrixAutoUpdate = false;
        if (built) holder.add(built());
        else if (/\.(glb|gltf)$/i.test(name)) {
            import("../vendor/three/examples/jsm/loaders/GLTFLoader.js").then(({ GLTFLoader }) => {
                new GLTFLoader().load(fileURL(name), (g) => { holder.add(g.scene); this.render(); },
                    undefined, () => holder.add(new THREE.Mesh(new THREE.BoxGeometry(s, s, s), mat)));
            });
        }
        return holder;
    }

    rebuild() {
        this.items.clear();
        const T = this.transforms;
        const positions = T.map((m) => new THREE.Vector3().setFromMatrixPosition(m));
        if (this.bool(["show_points"], true) && positions.length) {
            const geo = new THREE.BufferGeometry().setFromPoints(positions);
            const mat = new THREE.PointsMaterial({ color: new THREE.Color(this.str(["point_color"], "#e03030")), size: this.num(["point_size"], 8), sizeAttenuation: false });
            this.items.add(new THREE.Points(geo, mat));
        }
        if (this.bool(["show_lines"], false) && positions.length > 1) {
            const pairs = [];
            const spec = this.str(["line", "lines"]);
            if (spec) {
                for (const part of spec.split(",")) {
                    const [a, b] = part.split("-").map((s) => parseInt(s, 10));
                    if (positions[a] && positions[b]) pairs.push(positions[a], positions[b]);
                }
            } else {
                for (let i = 1; i < positions.length; i++) pairs.push(positions[i - 1], positions[i]);
            }
            const geo = new THREE.BufferGeometry().setFromPoints(pairs);
            const mat = new THREE.LineBasicMaterial({ color: new THREE.Color(this.str(["line_color"], "#3070e0")), linewidth: this.num(["line_width"], 1) });
            this.items.add(new THREE.LineSegments(geo, mat));
        }
        if (this.bool(["show_models"], false)) {
            while (this.models.length < T.length) this.models.push(this.model(this.models.length));
            T.forEach((m, i) => { this.models[i].matrix.copy(m); this.items.add(this.models[i]); });
        }
    }

    render() {
        const w = this.body.clientWidth, h = this.body.clientHeight;
        if (!w || !h) return;
        if (w !== this.w || h !== this.h) {
            this.w = w; this.h = h;
            this.renderer.setSize(w, h);
            this.camera.aspect = w / h;
            this.camera.updateProjectionMatrix();
        }
        const bg = this.str(["scene_background"], this.cssVar("--scene-background", "#202830"));
        this.scene.background = new THREE.Color(bg);
        this.renderer.render(this.scene, this.camera);
    }

    destroy() { this.renderer.dispose(); }
}
