// HTTP calls, the WebSocket and the decoding of binary data frames (docs/webui-protocol.md).

const TOKEN = new URLSearchParams(location.search).get("token");

function withToken(url) {
    if (!TOKEN) return url;
    return url + (url.includes("?") ? "&" : "?") + "token=" + encodeURIComponent(TOKEN);
}

function headers(extra = {}) {
    return TOKEN ? { ...extra, Authorization: "Bearer " + TOKEN } : extra;
}

export class ApiError extends Error {
    constructor(status, message) {
        super(message);
        this.status = status;
    }
}

async function answer(response) {
    let body = null;
    try { body = await response.json(); } catch { body = null; }
    if (!response.ok) {
        const message = body && body.error ? body.error : `${response.status} ${response.statusText}`;
        throw new ApiError(response.status, message);
    }
    return body;
}

export async function getJSON(url) {
    return answer(await fetch(withToken(url), { headers: headers(), cache: "no-store" }));
}

export async function postJSON(url, body) {
    return answer(await fetch(withToken(url), {
        method: "POST",
        headers: headers({ "Content-Type": "application/json" }),
        body: JSON.stringify(body),
    }));
}

/** A URL for a file beside the model (image widgets). */
export function fileURL(name) {
    return withToken("/files/" + name.split("/").map(encodeURIComponent).join("/"));
}

export const api = {
    network: () => getJSON("/api/network"),
    classes: () => getJSON("/api/classes"),
    status: () => getJSON("/api/status"),
    control: (state) => postJSON("/api/control", { state }),
    /** Counts parameter writes begun and ended, so a read that overlapped one can be dropped. */
    parameterWrites: 0,
    async setParameter(path, value, x = undefined, y = undefined) {
        const body = { path, value };
        if (x !== undefined && x !== null) body.x = x;
        if (y !== undefined && y !== null) body.y = y;
        this.parameterWrites++;
        try {
            return await postJSON("/api/parameter", body);
        } finally {
            this.parameterWrites++;
        }
    },
    command: (module, name, x = 0, y = 0, value = null) =>
        postJSON("/api/command", { module, name, x, y, value }),
    module: (path) => getJSON("/api/module?path=" + encodeURIComponent(path)),
    data: (paths) => getJSON("/api/data?paths=" + paths.map(encodeURIComponent).join(",")),
    log: (since = 0) => getJSON("/api/log?since=" + since),
};

/** Split a command path "Group.Module.cmd" into {module, name}. */
export function splitCommand(path) {
    const i = path.lastIndexOf(".");
    return i < 0 ? { module: "", name: path } : { module: path.slice(0, i), name: path.slice(i + 1) };
}

/**
 * Decode one binary data frame: 4 bytes little-endian header length N, N bytes of JSON,
 * then payloads at header offsets. Returns {tick, time, buffers: Map("path|format" -> item)}
 * where an item is {path, format, shape, data} with data a Float32Array (raw, history,
 * events; these two also keep their header fields) or a Blob (png/jpeg).
 */
export function decodeFrame(buffer) {
    const view = new DataView(buffer);
    const n = view.getUint32(0, true);
    const header = JSON.parse(new TextDecoder().decode(new Uint8Array(buffer, 4, n)));
    const base = 4 + n;
    const buffers = new Map();
    for (const b of header.buffers || []) {
        const start = base + b.offset;
        let data;
        if (b.format === "raw" || b.format === "history" || b.format === "events" || !b.format) {
            const bytes = buffer.slice(start, start + b.length);   // copy: keeps alignment
            if (littleEndian) {
                data = new Float32Array(bytes);
            } else {
                const dv = new DataView(bytes);
                data = new Float32Array(b.length / 4);
                for (let i = 0; i < data.length; i++) data[i] = dv.getFloat32(4 * i, true);
            }
        } else {
            data = new Blob([new Uint8Array(buffer, start, b.length)],
                { type: b.format === "png" ? "image/png" : "image/jpeg" });
        }
        // history/events buffers keep their header fields (mode, ticks, buffer_shape, ...)
        const item = { ...b, path: b.path, format: b.format || "raw", shape: b.shape || [], data };
        buffers.set(item.path + "|" + item.format, item);
    }
    return { tick: header.tick, time: header.time, buffers };
}

const littleEndian = new Uint8Array(new Uint16Array([1]).buffer)[0] === 1;

/**
 * The WebSocket: subscriptions, flow control ("ready"), pings, and reconnection.
 * Events (EventTarget): "open", "close", "status", "log", "network", "pong", "frame".
 */
export class Socket extends EventTarget {
    constructor() {
        super();
        this.ws = null;
        this.subscriptions = [];
        this.rtt = null;
        this.connected = false;
        this._pingTimer = null;
        this._retry = 500;
    }

    connect() {
        const scheme = location.protocol === "https:" ? "wss:" : "ws:";
        const ws = new WebSocket(withToken(`${scheme}//${location.host}/api/ws`));
        ws.binaryType = "arraybuffer";
        this.ws = ws;
        ws.onopen = () => {
            this.connected = true;
            this._retry = 500;
            this._send({ type: "subscribe", buffers: this.subscriptions });
            this.ready();
            this.ping();
            this._pingTimer = setInterval(() => this.ping(), 1000);
            this.dispatchEvent(new Event("open"));
        };
        ws.onclose = () => {
            this.connected = false;
            clearInterval(this._pingTimer);
            this.dispatchEvent(new Event("close"));
            setTimeout(() => this.connect(), this._retry);
            this._retry = Math.min(this._retry * 2, 5000);
        };
        ws.onmessage = (event) => {
            if (typeof event.data === "string") {
                let msg;
                try { msg = JSON.parse(event.data); } catch { return; }
                if (msg.type === "pong") {
                    this.rtt = performance.now() - msg.t;
                    this.dispatchEvent(new CustomEvent("pong", { detail: this.rtt }));
                } else if (msg.type) {
                    this.dispatchEvent(new CustomEvent(msg.type, { detail: msg }));
                }
            } else {
                let frame;
                try { frame = decodeFrame(event.data); } catch (e) { console.error(e); this.ready(); return; }
                this.dispatchEvent(new CustomEvent("frame", { detail: frame }));
            }
        };
    }

    _send(message) {
        if (this.ws && this.ws.readyState === WebSocket.OPEN) this.ws.send(JSON.stringify(message));
    }

    /** Replace the subscriptions: a list of {path, format}. Sent even when unchanged: new
     *  widgets need the histories again, which the server sends after every subscribe. */
    subscribe(list) {
        this.subscriptions = list;
        this._send({ type: "subscribe", buffers: list });
        this.ready();
    }

    ready() { this._send({ type: "ready" }); }

    ping() { this._send({ type: "ping", t: performance.now() }); }
}
